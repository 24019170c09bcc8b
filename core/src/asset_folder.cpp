// A scene's mesh assets taken from a folder of built assets (gfield-view --assets).

#include "gfield/file_read.hpp"
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
  // Whatever lies at an asset's path is the asset: one that cannot be read (a folder, a FIFO, a
  // dangling link) is an error when it is loaded, not a silent fall back to the BVH.
  for (MeshAsset& mesh : scene.meshes) {
    const std::string stem = (fs::path(dir) / mesh.asset).string();
    if (file_problem(stem + ".gimage.exr") != "no such file")
      mesh.geometry_image = stem + ".gimage.exr";
    if (file_problem(stem + ".gfield.exr") != "no such file")
      mesh.geometry_field = stem + ".gfield.exr";
  }
  return true;
}

}  // namespace gfield
