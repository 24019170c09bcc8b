#include "geometry/mesh_formats.hpp"

#include <array>

#include "geometry/gltf_mesh.hpp"
#include "geometry/mesh_readers.hpp"
#include "geometry/mesh_side_files.hpp"
#include "gfield/file_extension.hpp"

namespace gfield {
namespace {

constexpr std::array<MeshFormat, 6> kFormats = {{
    {".obj", read_obj, obj_side_files, true},
    {".ply", read_ply, ply_side_files, true},
    {".off", read_off, nullptr, true},
    {".stl", read_stl, nullptr, true},
    {".gltf", nullptr, gltf_external_files, false},
    {".glb", nullptr, gltf_external_files, false},
}};

std::string extension_list(bool batch_only) {
  std::string list;
  for (const MeshFormat& format : kFormats) {
    if (format.batch || !batch_only) {
      list += (list.empty() ? "" : ", ") + std::string(format.extension);
    }
  }
  return list;
}

}  // namespace

std::span<const MeshFormat> mesh_formats() {
  return kFormats;
}

const MeshFormat* find_mesh_format(const std::string& path) {
  const std::string extension = lower_extension(path);
  for (const MeshFormat& format : kFormats) {
    if (format.extension == extension) {
      return &format;
    }
  }
  return nullptr;
}

std::string mesh_extension_list() {
  return extension_list(false);
}

std::string batch_extension_list() {
  return extension_list(true);
}

std::vector<std::string> mesh_side_files(const std::string& path, OutsidePaths outside) {
  const MeshFormat* format = find_mesh_format(path);
  if (format == nullptr || format->side_files == nullptr) {
    return {};
  }
  return format->side_files(path, outside);
}

}  // namespace gfield
