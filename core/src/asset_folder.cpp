// A scene's mesh assets taken from a folder of built assets (gfield-view --assets).

#include "gfield/scene.hpp"

#include <filesystem>

namespace gfield {
namespace fs = std::filesystem;

bool use_asset_folder(const std::string& dir, Scene& scene, std::string& error) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    error = dir + ": not a folder";
    return false;
  }
  for (MeshAsset& mesh : scene.meshes) {
    const std::string stem = (fs::path(dir) / mesh.asset).string();
    if (fs::is_regular_file(stem + ".gimage.exr", ec))
      mesh.geometry_image = stem + ".gimage.exr";
    if (fs::is_regular_file(stem + ".gfield.exr", ec))
      mesh.geometry_field = stem + ".gfield.exr";
  }
  return true;
}

}  // namespace gfield
