#include "geometry/scene_file.hpp"

#include <algorithm>
#include <map>

#include "geometry/gltf_scene.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Replaces the glTF objects of a JSON scene by the mesh objects of their files, in place.
bool expand_includes(Scene& scene, OutsidePaths outside, std::vector<std::string>& warnings,
                     std::string& error) {
  std::vector<SceneObject> objects;
  size_t next = 0;
  for (const SceneInclude& include : scene.includes) {
    while (next < include.position && next < scene.objects.size())
      objects.push_back(std::move(scene.objects[next++]));
    Scene part;
    part.meshes = std::move(scene.meshes);
    if (!append_gltf_objects(include.file, outside, object_to_world(include.transform), part,
                             warnings, error)) {
      error = include.where + ": " + error;
      return false;
    }
    scene.meshes = std::move(part.meshes);
    for (SceneObject& o : part.objects) {
      o.name = include.name.empty() ? o.name : include.name + "/" + o.name;
      objects.push_back(std::move(o));
    }
    if (objects.size() > kMaxSceneObjects) {
      error = include.where + ": the scene holds more than " + std::to_string(kMaxSceneObjects) +
              " objects";
      return false;
    }
  }
  while (next < scene.objects.size())
    objects.push_back(std::move(scene.objects[next++]));
  scene.objects = std::move(objects);
  scene.includes.clear();
  return true;
}

/// A box: lo > hi when empty.
using Bounds = std::pair<glm::dvec3, glm::dvec3>;

/// The world bounds of object `o` of `scene`: an analytic shape's, or its mesh file's points
/// (each mesh read once, into `meshes`), placed by its transform.
bool world_bounds(const Scene& scene, const SceneObject& o, std::map<int, Bounds>& meshes,
                  Bounds& world, std::string& error) {
  Bounds local;
  shape_bounds(o.shape, local.first, local.second);
  if (o.shape.type == ShapeType::kMesh && !meshes.count(o.shape.mesh)) {
    const MeshAsset& asset = scene.meshes[size_t(o.shape.mesh)];
    TriangleMesh mesh;
    std::vector<std::string> ignored;  // the scene's readers report them
    if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, mesh, nullptr, ignored,
                   error))
      return false;
    Bounds& b = meshes[o.shape.mesh] = {glm::dvec3(1e300), glm::dvec3(-1e300)};
    for (const glm::dvec3& p : mesh.positions)
      b = {glm::min(b.first, p), glm::max(b.second, p)};
  }
  if (o.shape.type == ShapeType::kMesh)
    local = meshes[o.shape.mesh];
  const glm::dmat4 m = object_to_world(o.transform);
  world = {glm::dvec3(1e300), glm::dvec3(-1e300)};
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 corner(c & 1 ? local.second.x : local.first.x,
                            c & 2 ? local.second.y : local.first.y,
                            c & 4 ? local.second.z : local.first.z);
    const glm::dvec3 w(m * glm::dvec4(corner, 1.0));
    world = {glm::min(world.first, w), glm::max(world.second, w)};
  }
  return true;
}

/// "'NAME' (object K)", or "object K".
std::string object_name(const Scene& scene, size_t k) {
  const std::string& name = scene.objects[k].name;
  return (name.empty() ? "" : "'" + name + "' (") + "object " + std::to_string(k) +
         (name.empty() ? "" : ")");
}

/// Dielectrics must not overlap (the outside of each is air), which gfield cannot check on the
/// solids: a warning for dielectric objects whose world bounding boxes intersect (they may, where
/// the solids do not: a sphere in a tube's hole). False with a mesh's error.
bool warn_overlapping_dielectrics(const Scene& scene, std::vector<std::string>& warnings,
                                  std::string& error) {
  std::vector<std::pair<size_t, Bounds>> dielectrics;
  std::map<int, Bounds> meshes;
  for (size_t k = 0; k < scene.objects.size(); ++k) {
    Bounds world;
    if (scene.objects[k].material.type != MaterialType::kDielectric)
      continue;
    if (!world_bounds(scene, scene.objects[k], meshes, world, error))
      return false;
    dielectrics.emplace_back(k, world);
  }
  size_t pairs = 0;
  std::string first;
  for (size_t i = 0; i < dielectrics.size(); ++i) {
    for (size_t j = i + 1; j < dielectrics.size(); ++j) {
      const Bounds& a = dielectrics[i].second;
      const Bounds& b = dielectrics[j].second;
      if (!glm::all(glm::lessThan(a.first, b.second)) ||
          !glm::all(glm::lessThan(b.first, a.second)))
        continue;
      if (pairs++ == 0)
        first = object_name(scene, dielectrics[i].first) + " and " +
                object_name(scene, dielectrics[j].first);
    }
  }
  if (pairs > 0)
    warnings.push_back(scene.filename + ": the dielectrics " + first +
                       " have intersecting bounding boxes" +
                       (pairs > 1 ? " (and " + std::to_string(pairs - 1) + " more pairs)" : "") +
                       "; dielectrics must not overlap (gfield takes the outside of each for air), "
                       "so where their solids do the picture is wrong");
  return true;
}

}  // namespace

bool resolve_mesh_materials(Scene& scene, std::vector<std::string>& warnings, std::string& error) {
  std::vector<int> carries(scene.meshes.size(), -1);  // -1: not read yet
  for (SceneObject& o : scene.objects) {
    Material& m = o.material;
    if (o.shape.type != ShapeType::kMesh || m.type != MaterialType::kDiffuse ||
        !(m.texture_by_mesh || (m.texture == TextureType::kMesh && m.default_color)))
      continue;
    int& known = carries[size_t(o.shape.mesh)];
    if (known < 0) {
      const MeshAsset& asset = scene.meshes[size_t(o.shape.mesh)];
      TriangleMesh mesh;
      MeshAppearance appearance;
      if (!load_mesh(MeshSource{asset.file, asset.part, asset.outside_paths}, mesh, &appearance,
                     warnings, error))
        return false;
      known = carries_base_color(appearance) ? 1 : 0;
    }
    if (m.texture_by_mesh && known == 1)
      m.texture = TextureType::kMesh;
    if (m.texture == TextureType::kMesh && m.default_color)
      m.color = glm::vec3(1.0f);
    m.texture_by_mesh = false;
  }
  return true;
}

bool load_scene_file(const std::string& filename, Scene& scene, std::vector<std::string>& warnings,
                     std::string& error, OutsidePaths outside) {
  Scene result;
  const bool ok = is_gltf_file(filename)
                      ? load_gltf_scene(filename, outside, result, warnings, error)
                      : load_scene(filename, result, error, outside) &&
                            expand_includes(result, outside, warnings, error);
  if (!ok || !resolve_mesh_materials(result, warnings, error) ||
      !warn_overlapping_dielectrics(result, warnings, error))
    return false;
  scene = std::move(result);
  return true;
}

}  // namespace gfield
