#include "geometry/mesh_io.hpp"

#include <filesystem>

#include "geometry/gltf_mesh.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_formats.hpp"
#include "geometry/mesh_readers.hpp"
#include "gfield/file_extension.hpp"
#include "gfield/file_read.hpp"
#include "gfield/limits.hpp"

namespace gfield {

namespace {

/// The appearance of what a reader of `source` read: corner uvs from their indices, the
/// materials with their libraries (OBJ) or the file's texture (PLY), the textures decoded (or
/// their headers read).
bool soup_appearance(const MeshSource& source, MeshSoup& soup, MeshAppearance& appearance,
                     std::vector<std::string>& warnings, std::string& error) {
  const std::string& filename = source.file;
  appearance = MeshAppearance{};
  appearance.corner_uv.reserve(soup.corner_uvs.size());
  for (const std::int32_t index : soup.corner_uvs) {
    appearance.corner_uv.push_back(index >= 0 ? soup.uvs[size_t(index)] : glm::vec2(0.0f));
  }
  if (!soup.libraries.empty() &&
      !read_material_libraries(filename, source.outside_paths, soup, warnings, error)) {
    return false;
  }
  const std::filesystem::path folder = std::filesystem::path(filename).parent_path();
  if (soup.libraries.empty() && !soup.texture_files.empty()) {  // PLY: one texture for all
    soup.texture_files.resize(1);
    const std::string name = soup.texture_files[0];
    std::string problem;
    if (!resolve_named_path(folder, name, folder, source.outside_paths, soup.texture_files[0],
                            problem)) {
      error = filename + ": comment TextureFile " + problem;
      return false;
    }
    soup.materials = {{"TextureFile", glm::vec3(1.0f), 0}};
    soup.face_material.assign(soup.mesh.triangles.size(), 0);
  }
  appearance.vertex_color = std::move(soup.vertex_color);
  appearance.face_material = std::move(soup.face_material);
  appearance.materials = std::move(soup.materials);
  return load_texture_files(filename, soup.texture_files, source.texture_pixels, appearance,
                            warnings, error);
}

}  // namespace

bool is_gltf_file(const std::string& filename) {
  const MeshFormat* format = find_mesh_format(filename);
  return format != nullptr && format->read == nullptr;
}

bool load_mesh(const std::string& filename, TriangleMesh& mesh, std::string& error,
               MeshLoadStats* stats) {
  std::vector<std::string> warnings;
  return load_mesh(MeshSource{filename, ""}, mesh, nullptr, warnings, error, stats);
}

bool load_mesh(const MeshSource& source, TriangleMesh& mesh, MeshAppearance* appearance,
               std::vector<std::string>& warnings, std::string& error, MeshLoadStats* stats) {
  const std::string& filename = source.file;
  const MeshFormat* format = find_mesh_format(filename);
  if (format != nullptr && format->read == nullptr) {
    return load_gltf_mesh(source, mesh, appearance, warnings, error, stats);
  }
  if (!source.part.empty()) {
    error = filename + ": --mesh " + source.part + " applies to glTF files only";
    return false;
  }
  if (format == nullptr) {
    error = filename + ": unknown mesh extension '" + lower_extension(filename) + "' (expected " +
            mesh_extension_list() + ")";
    return false;
  }
  std::string data;
  if (!read_file(filename, kMaxMeshFileBytes, data, error)) {
    return false;
  }
  MeshSoup soup;
  ReadFailure failure;
  if (!format->read(data, soup, failure)) {
    error = filename;
    if (failure.line > 0) {
      error += ':' + std::to_string(failure.line);
    }
    error += ": " + failure.what;
    return false;
  }
  if (soup.mesh.triangles.empty()) {
    error = filename + ": no faces (" + std::to_string(soup.mesh.positions.size()) +
            " vertices read; triangle strips and point clouds are not supported)";
    return false;
  }
  if (appearance != nullptr && !soup_appearance(source, soup, *appearance, warnings, error)) {
    return false;
  }
  mesh = std::move(soup.mesh);
  if (stats) {
    *stats = soup.stats;
  }
  return true;
}

}  // namespace gfield
