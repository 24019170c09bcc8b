#include "preprocess/batch_plan.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "geometry/mesh_formats.hpp"
#include "gfield/file_read.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// A file of a format `gfield batch` takes from a folder (geometry/mesh_formats.hpp).
bool is_batch_mesh_file(const fs::path& path) {
  const MeshFormat* format = find_mesh_format(path.string());
  return format != nullptr && format->batch;
}

bool parse_int(std::string_view text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

/// The mesh files of `folder` (sorted); entries named like meshes that cannot be read as files
/// go to `skipped` ("PATH: why").
std::vector<std::string> folder_meshes(const std::string& folder,
                                       std::vector<std::string>& skipped) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, ec)) {
    const std::string file = entry.path().filename().string();
    if (!is_batch_mesh_file(entry.path()) || file.find(".gimage.") != std::string::npos)
      continue;
    if (const std::string why = file_problem(entry.path().string()); !why.empty())
      skipped.push_back(entry.path().string() + ": " + why);
    else
      found.push_back(entry.path().string());
  }
  std::sort(found.begin(), found.end());
  std::sort(skipped.begin(), skipped.end());
  return found;
}

bool list_meshes(const std::string& list_file, std::vector<std::string>& meshes,
                 std::string& error) {
  std::ifstream list(list_file);
  if (!list) {
    error = list_file + ": cannot read the list";
    return false;
  }
  for (std::string line; std::getline(list, line);) {
    line.erase(0, line.find_first_not_of(" \t\r"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line.empty() || line[0] == '#') {
      continue;
    }
    const fs::path path(line);
    meshes.push_back(path.is_absolute() ? line
                                        : (fs::path(list_file).parent_path() / path).string());
  }
  return true;
}

}  // namespace

bool parse_shard(const std::string& text, Shard& shard, std::string& error) {
  const size_t slash = text.find('/');
  Shard s;
  if (slash == std::string::npos || !parse_int(std::string_view(text).substr(0, slash), s.index) ||
      !parse_int(std::string_view(text).substr(slash + 1), s.count)) {
    error = "--shard " + text + ": expected I/N (task I of N, 0 <= I < N)";
    return false;
  }
  if (s.count < 1 || s.index < 0 || s.index >= s.count) {
    error = "--shard " + text + ": needs N >= 1 and 0 <= I < N";
    return false;
  }
  shard = s;
  return true;
}

std::string shard_label(const Shard& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

bool collect_batch(const std::vector<std::string>& inputs, const std::string& dir,
                   std::vector<BatchMesh>& meshes, std::vector<std::string>& skipped,
                   std::string& error) {
  std::vector<std::string> paths;
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (fs::is_directory(input, ec)) {
      const std::vector<std::string> found = folder_meshes(input, skipped);
      paths.insert(paths.end(), found.begin(), found.end());
    } else if (!fs::exists(input, ec)) {
      error = input + ": no such file or folder";
      return false;
    } else if (fs::path(input).extension() == ".txt") {
      if (!list_meshes(input, paths, error)) {
        return false;
      }
    } else {
      paths.push_back(input);
    }
  }
  std::set<std::string> seen;
  std::map<std::string, std::string> asset_of;  // asset -> mesh
  meshes.clear();
  for (const std::string& path : paths) {
    if (!seen.insert(fs::path(path).lexically_normal().string()).second) {
      continue;
    }
    const std::string asset = (fs::path(dir) / fs::path(path).stem()).string();
    if (const auto [it, inserted] = asset_of.emplace(asset, path); !inserted) {
      error = it->second + " and " + path + " would both build " + asset;
      return false;
    }
    meshes.push_back({path, asset});
  }
  if (meshes.empty()) {
    error = "batch: no mesh files in the inputs";
    return false;
  }
  return true;
}

std::vector<BatchMesh> shard_meshes(const std::vector<BatchMesh>& meshes, const Shard& shard) {
  std::vector<BatchMesh> out;
  for (size_t k = size_t(shard.index); k < meshes.size(); k += size_t(shard.count)) {
    out.push_back(meshes[k]);
  }
  return out;
}

bool prepare_output_folder(const std::string& dir, std::string& error) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) {
    error = dir + ": the output folder is a file";
    return false;
  }
  fs::create_directories(dir, ec);
  if (ec) {
    error = dir + ": cannot create the output folder (" + ec.message() + ")";
    return false;
  }
  const std::string probe =
      (fs::path(dir) / (".gfield-write-probe-" + std::to_string(::getpid()))).string();
  const int fd = ::open(probe.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = dir + ": the output folder is not writable (" + std::strerror(errno) + ")";
    return false;
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

}  // namespace gfield
