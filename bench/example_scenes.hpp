#pragma once
// The example scenes of data/scenes for the GL benchmarks: every mesh object's assets built by
// the `gfield` CLI with its defaults (as scripts/demo.sh builds them) into a folder, and the
// scene rewritten to point at them. Needs gfield::build_paths::cli() and
// gfield::build_paths::data_dir().

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "test_support/build_paths.hpp"

namespace gfield {

/// A fresh folder of the process's own for a benchmark's assets (temp/NAME-PID), removed when
/// it ends: assets of another build (another format) are never taken for this one's.
struct BenchFolder {
  std::filesystem::path path;
  explicit BenchFolder(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~BenchFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  BenchFolder(const BenchFolder&) = delete;
  BenchFolder& operator=(const BenchFolder&) = delete;
};

/// Runs `gfield ARGUMENTS` quietly; false (with the command on stderr) when it fails.
inline bool run_gfield_cli(const std::string& arguments) {
  const std::string command =
      std::string("\"") + gfield::build_paths::cli() + "\" " + arguments + " > /dev/null";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "%s failed\n", command.c_str());
    return false;
  }
  return true;
}

/// data/scenes/NAME.json with its meshes' geometry images and fields (and, with
/// `thickness_maps`, their d_n maps for wyman2005) built into `dir` unless already there; the
/// rewritten scene's path in `out` (it names them by absolute path: read it with outside paths
/// allowed).
inline bool prepare_example_scene(const std::string& name, const std::filesystem::path& dir,
                                  bool thickness_maps, std::string& out) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(gfield::build_paths::data_dir()) / "scenes" / (name + ".json");
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source));
  for (auto& object : scene["objects"]) {
    if (object["shape"] != "mesh")
      continue;
    const fs::path mesh =
        fs::weakly_canonical(source.parent_path() / object["file"].get<std::string>());
    const std::string asset = (dir / mesh.stem()).string();
    if (!fs::exists(asset + ".gfield.exr") &&
        !run_gfield_cli("build \"" + mesh.string() + "\" -o \"" + asset + "\" --verify-rays 0"))
      return false;
    if (thickness_maps && !fs::exists(asset + ".thickness.exr") &&
        !run_gfield_cli("thickness \"" + asset + "\""))
      return false;
    object["file"] = mesh.string();
    object["gimage"] = asset + ".gimage.exr";
    object["gfield"] = asset + ".gfield.exr";
  }
  out = (dir / (name + ".json")).string();
  std::ofstream(out) << scene.dump(2);
  return true;
}

}  // namespace gfield
