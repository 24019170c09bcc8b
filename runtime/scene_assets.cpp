#include "runtime/scene_assets.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "geometry/scene_file.hpp"
#include "gfield/asset_source.hpp"
#include "gfield/child_program.hpp"
#include "gfield/printable.hpp"
#include "gfield/thickness.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// Runs `argv` with its stdout sent to our stderr (gfield-view's stdout is its own report); its
/// exit code, or -1 when it could not be started.
int run_gfield(std::vector<std::string> argv) {
  int status = 0;
  return run_child(std::move(argv), true, status) ? child_exit_code(status) : -1;
}

bool has_gltf_meshes(const Scene& scene) {
  return std::any_of(scene.meshes.begin(), scene.meshes.end(),
                     [](const MeshAsset& m) { return !m.part.empty(); });
}

}  // namespace

std::string gfield_executable() {
  return sibling_executable("GFIELD_CLI", "gfield", GFIELD_BUILD_TREE_CLI);
}

namespace {

/// Rebuilds the asset of `mesh` (NAME of its NAME.gimage.exr) from its mesh file with the
/// default options.
bool rebuild_asset(const MeshAsset& mesh, std::string& error) {
  const std::string image = mesh.geometry_image;
  const std::string name = image.substr(0, image.size() - std::string(".gimage.exr").size());
  std::fprintf(stderr, "gfield-view: rebuilding %s from %s (--rebuild-stale)\n",
               printable(name).c_str(), printable(mesh.file).c_str());
  const int status = run_gfield({gfield_executable(), "build", mesh.file, "-o", name});
  if (status == 0)
    return true;
  error = name + ": rebuilding it from " + mesh.file + " failed (gfield build " +
          (status < 0 ? "could not be started" : "exited with " + std::to_string(status)) + ")";
  return false;
}

/// check_scene_assets, rebuilding each stale asset once with `rebuild_stale`.
bool check_or_rebuild_assets(const Scene& scene, bool rebuild_stale, std::string& error) {
  std::vector<char> rebuilt(scene.meshes.size(), 0);
  int stale = -1;
  while (!check_scene_assets(scene, stale, error)) {
    if (!rebuild_stale || stale < 0 || rebuilt[size_t(stale)])
      return false;
    rebuilt[size_t(stale)] = 1;
    if (!rebuild_asset(scene.meshes[size_t(stale)], error))
      return false;
  }
  return true;
}

}  // namespace

bool load_view_scene(const std::string& filename, const std::string& asset_dir,
                     OutsidePaths outside, bool rebuild_stale, Scene& scene, std::string& error) {
  std::vector<std::string> warnings;
  if (!load_scene_file(filename, scene, warnings, error, outside))
    return false;
  for (const std::string& w : warnings)
    std::fprintf(stderr, "gfield-view: warning: %s\n", printable(w).c_str());
  if (has_gltf_meshes(scene)) {
    std::vector<std::string> command = {gfield_executable(), "assets", filename};
    if (!asset_dir.empty())
      command.insert(command.end(), {"--assets", asset_dir});
    if (outside == OutsidePaths::kAllowed)
      command.push_back("--allow-outside-paths");
    const int status = run_gfield(command);
    if (status != 0) {
      error = filename + ": building its glTF meshes' assets failed (" + command[0] + " assets " +
              (status < 0 ? "could not be started" : "exited with " + std::to_string(status)) + ")";
      return false;
    }
    warnings.clear();
    if (!load_scene_file(filename, scene, warnings, error, outside))
      return false;
  }
  if (!asset_dir.empty() && !use_asset_folder(asset_dir, scene, error)) {
    error = "--assets " + error;
    return false;
  }
  return check_or_rebuild_assets(scene, rebuild_stale, error);
}

bool build_thickness_maps(const Scene& scene, std::string& error) {
  std::vector<char> needed(scene.meshes.size(), 0);
  for (const SceneObject& o : scene.objects)
    if (o.shape.type == ShapeType::kMesh && o.material.type == MaterialType::kDielectric)
      needed[size_t(o.shape.mesh)] = 1;
  const std::string suffix = ".gimage.exr";
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const std::string& image = scene.meshes[m].geometry_image;
    if (!needed[m] || image.size() <= suffix.size())
      continue;  // no geometry image: the method says which asset is missing
    const std::string map = thickness_path(image);
    std::error_code ec, ec_image;
    const auto made = fs::last_write_time(map, ec), built = fs::last_write_time(image, ec_image);
    if (!ec && !ec_image && made >= built)
      continue;
    const std::string name = image.substr(0, image.size() - suffix.size());
    const int status = run_gfield({gfield_executable(), "thickness", name});
    if (status != 0) {
      error = map + ": making it failed (gfield thickness " + name + " " +
              (status < 0 ? "could not be started" : "exited with " + std::to_string(status)) + ")";
      return false;
    }
  }
  return true;
}

}  // namespace gfield
