// gfield batch INPUT... -o DIR: `gfield build` over folders, mesh files and lists of meshes.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "preprocess/cli/asset_options.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {
namespace {

bool is_mesh_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".obj" || ext == ".ply" || ext == ".off" || ext == ".stl";
}

/// The meshes of the inputs: a folder gives its mesh files (sorted, not recursive, no
/// *.gimage.obj), a .txt file one path per line (blank lines and # comments skipped, relative
/// to the list), anything else is taken as a mesh file.
std::vector<std::string> collect_meshes(const std::vector<std::string>& inputs) {
  namespace fs = std::filesystem;
  std::vector<std::string> meshes;
  for (const std::string& input : inputs) {
    if (fs::is_directory(input)) {
      std::vector<std::string> found;
      for (const fs::directory_entry& entry : fs::directory_iterator(input)) {
        const std::string file = entry.path().filename().string();
        if (entry.is_regular_file() && is_mesh_file(entry.path()) &&
            file.find(".gimage.") == std::string::npos) {
          found.push_back(entry.path().string());
        }
      }
      std::sort(found.begin(), found.end());
      meshes.insert(meshes.end(), found.begin(), found.end());
    } else if (fs::path(input).extension() == ".txt") {
      std::ifstream list(input);
      if (!list) {
        throw CommandError(input + ": cannot read the list");
      }
      std::string line;
      while (std::getline(list, line)) {
        line.erase(0, line.find_first_not_of(" \t\r"));
        line.erase(line.find_last_not_of(" \t\r") + 1);
        if (line.empty() || line[0] == '#') {
          continue;
        }
        const fs::path path(line);
        meshes.push_back(path.is_absolute() ? line
                                            : (fs::path(input).parent_path() / path).string());
      }
    } else {
      meshes.push_back(input);
    }
  }
  return meshes;
}

void print_progress(size_t done, size_t total, const std::string& what) {
  constexpr int kWidth = 30;
  const int filled = total == 0 ? kWidth : int(kWidth * done / total);
  std::fprintf(stderr, "[%s%s] %zu/%zu %s\n", std::string(size_t(filled), '#').c_str(),
               std::string(size_t(kWidth - filled), '.').c_str(), done, total, what.c_str());
}

}  // namespace

void add_batch_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "batch",
      "Run `gfield build` for every mesh of the inputs (folders of meshes, mesh files, or .txt\n"
      "lists with one mesh path per line) into DIR/<mesh name>.*. Skips meshes whose outputs\n"
      "are newer than the mesh (unless --force), keeps going past meshes that fail, and exits\n"
      "with an error listing them at the end.");
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto dir = std::make_shared<std::string>();
  auto force = std::make_shared<bool>(false);
  auto args = std::make_shared<AssetArguments>();
  cmd->add_option("INPUT", *inputs, "folders, mesh files or .txt lists")->required();
  cmd->add_option("-o,--output", *dir, "output folder")->required();
  cmd->add_flag("--force", *force, "rebuild outputs that are up to date");
  add_asset_options(cmd, args);
  cmd->callback([inputs, dir, force, args] {
    namespace fs = std::filesystem;
    const std::vector<std::string> meshes = collect_meshes(*inputs);
    if (meshes.empty()) {
      throw CommandError("batch: no mesh files in the inputs");
    }
    std::error_code ec;
    fs::create_directories(*dir, ec);
    const AssetOptions options = asset_options(*args);
    std::vector<std::string> failed;
    size_t built = 0;
    size_t skipped = 0;
    for (size_t i = 0; i < meshes.size(); ++i) {
      const std::string& mesh = meshes[i];
      const std::string name = (fs::path(*dir) / fs::path(mesh).stem()).string();
      print_progress(i, meshes.size(), mesh);
      if (!*force && asset_up_to_date(mesh, name)) {
        std::printf("%s: up to date (%s.*)\n", mesh.c_str(), name.c_str());
        ++skipped;
        continue;
      }
      nlohmann::json report;
      std::string error;
      const auto start = std::chrono::steady_clock::now();
      bool ok = false;
      try {
        ok = build_asset(mesh, name, options, report, error);
      } catch (const std::exception& e) {
        error = mesh + ": " + e.what();
      }
      if (ok) {
        ++built;
        std::printf(
            "%s: %s (%.1f s)\n", mesh.c_str(), asset_summary(report).c_str(),
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      } else {
        failed.push_back(mesh);
        std::printf("%s: FAILED: %s\n", mesh.c_str(), error.c_str());
      }
      std::fflush(stdout);
    }
    print_progress(meshes.size(), meshes.size(), "done");
    std::printf("batch: %zu built, %zu up to date, %zu failed\n", built, skipped, failed.size());
    if (!failed.empty()) {
      std::string list;
      for (const std::string& f : failed) {
        list += (list.empty() ? "" : ", ") + f;
      }
      throw CommandError("batch: " + std::to_string(failed.size()) + " of " +
                         std::to_string(meshes.size()) + " meshes failed: " + list);
    }
  });
}

}  // namespace gfield
