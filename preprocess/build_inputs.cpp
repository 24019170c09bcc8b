#include "preprocess/build_inputs.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/gltf_mesh.hpp"
#include "gfield/content_hash.hpp"
#include "gfield/file_read.hpp"
#include "gfield/printable.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// Scheme of the hashed record; bump when what it holds changes meaning.
/// 2: geometry images hold the mesh's albedo (format version 2).
constexpr int kBuildIdScheme = 2;

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

std::vector<std::string> mesh_texture_files(const std::string& mesh_path, OutsidePaths outside) {
  std::string ext = fs::path(mesh_path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  std::vector<std::string> files;
  if (ext == ".gltf" || ext == ".glb") {
    return gltf_external_files(mesh_path, outside);
  }
  const fs::path folder = fs::path(mesh_path).parent_path();
  if (ext == ".ply") {  // "comment TextureFile NAME" in the header
    std::ifstream in(mesh_path, std::ios::binary);
    for (std::string line; std::getline(in, line) && line.rfind("end_header", 0) != 0;) {
      const std::vector<std::string> t = tokens(line);
      if (t.size() >= 3 && t[0] == "comment" && t[1] == "TextureFile") {
        add_named(folder, t[2], folder, outside, files);
      }
    }
    return files;
  }
  if (ext != ".obj") {
    return files;
  }
  std::ifstream in(mesh_path);
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

bool hash_build_inputs(const std::string& mesh_path, const nlohmann::json& options,
                       OutsidePaths outside, BuildInputs& inputs, std::string& error) {
  if (const std::string problem = file_problem(mesh_path); !problem.empty()) {
    error = mesh_path + ": " + (problem == "no such file" ? "no such mesh file" : problem);
    return false;
  }
  std::error_code ec;
  std::string mesh_hash;
  if (!sha256_file(mesh_path, mesh_hash, error)) {
    return false;
  }
  nlohmann::json textures = nlohmann::json::array();
  const fs::path mesh_folder = fs::path(mesh_path).parent_path();
  for (const std::string& file : mesh_texture_files(mesh_path, outside)) {
    std::string hash;
    std::string ignored;
    const bool found = fs::is_regular_file(file, ec) && sha256_file(file, hash, ignored);
    textures.push_back(
        {{"file", printable(fs::path(file).lexically_relative(mesh_folder).string())},
         {"sha256", found ? nlohmann::json(hash) : nlohmann::json()}});
  }
  inputs.record = {{"scheme", kBuildIdScheme},
                   {"gfield", GFIELD_VERSION},
                   {"mesh",
                    {{"file", printable(fs::path(mesh_path).filename().string())},
                     {"bytes", fs::file_size(mesh_path, ec)},
                     {"sha256", mesh_hash}}},
                   {"textures", std::move(textures)},
                   {"options", options}};
  inputs.build_id = sha256_hex(inputs.record.dump()).substr(0, kBuildIdDigits);
  return true;
}

}  // namespace gfield
