#include "geometry/mesh_side_files.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// MTL keys whose last token names a texture file.
constexpr const char* kTextureKeys[] = {"map_Ka", "map_Kd",   "map_Ks", "map_Ke", "map_Ns",
                                        "map_d",  "map_bump", "bump",   "disp",   "decal",
                                        "refl",   "norm",     "map_Pr", "map_Pm", "map_Ps"};

/// The whitespace-separated tokens of `line`.
std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string t; in >> t;) {
    out.push_back(t);
  }
  return out;
}

bool is_texture_key(const std::string& key) {
  return std::find_if(std::begin(kTextureKeys), std::end(kTextureKeys),
                      [&](const char* k) { return key == k; }) != std::end(kTextureKeys);
}

/// Appends `name`, named by a file in `base`, to `files` when it may be read (inside `root`, or
/// anywhere when `outside` is kAllowed: confined_path.hpp); false when it may not.
bool add_named(const fs::path& base, const std::string& name, const fs::path& root,
               OutsidePaths outside, std::vector<std::string>& files) {
  std::string file, problem;
  if (!resolve_named_path(base, name, root, outside, file, problem))
    return false;
  files.push_back(file);
  return true;
}

/// Texture maps named by the MTL file `mtl` (paths relative to its folder), those that may be
/// read from `root` (the OBJ file's folder).
void add_material_maps(const fs::path& mtl, const fs::path& root, OutsidePaths outside,
                       std::vector<std::string>& files) {
  std::ifstream in(mtl);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> t = tokens(line);
    if (t.size() >= 2 && is_texture_key(t[0])) {
      add_named(mtl.parent_path(), t.back(), root, outside, files);
    }
  }
}

}  // namespace

std::vector<std::string> obj_side_files(const std::string& obj, OutsidePaths outside) {
  const fs::path folder = fs::path(obj).parent_path();
  std::vector<std::string> files;
  std::ifstream in(obj);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("mtllib", 0) != 0) {
      continue;
    }
    const std::vector<std::string> t = tokens(line);
    for (size_t i = 1; i < t.size(); ++i) {
      if (add_named(folder, t[i], folder, outside, files)) {
        const fs::path mtl = files.back();
        add_material_maps(mtl, folder, outside, files);
      }
    }
  }
  return files;
}

std::vector<std::string> ply_side_files(const std::string& ply, OutsidePaths outside) {
  const fs::path folder = fs::path(ply).parent_path();
  std::vector<std::string> files;
  std::ifstream in(ply, std::ios::binary);
  for (std::string line; std::getline(in, line) && line.rfind("end_header", 0) != 0;) {
    const std::vector<std::string> t = tokens(line);
    if (t.size() >= 3 && t[0] == "comment" && t[1] == "TextureFile") {
      add_named(folder, t[2], folder, outside, files);
    }
  }
  return files;
}

}  // namespace gfield
