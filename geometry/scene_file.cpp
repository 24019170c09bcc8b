#include "geometry/scene_file.hpp"

#include <algorithm>

#include "geometry/gltf_scene.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// Replaces the glTF objects of a JSON scene by the mesh objects of their files, in place.
bool expand_includes(Scene& scene, std::vector<std::string>& warnings, std::string& error) {
  std::vector<SceneObject> objects;
  size_t next = 0;
  for (const SceneInclude& include : scene.includes) {
    while (next < include.position && next < scene.objects.size())
      objects.push_back(std::move(scene.objects[next++]));
    Scene part;
    part.meshes = std::move(scene.meshes);
    if (!append_gltf_objects(include.file, object_to_world(include.transform), part, warnings,
                             error)) {
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
      if (!load_mesh(MeshSource{asset.file, asset.part}, mesh, &appearance, warnings, error))
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
                     std::string& error) {
  Scene result;
  const bool ok = is_gltf_file(filename) ? load_gltf_scene(filename, result, warnings, error)
                                         : load_scene(filename, result, error) &&
                                               expand_includes(result, warnings, error);
  if (!ok || !resolve_mesh_materials(result, warnings, error))
    return false;
  scene = std::move(result);
  return true;
}

}  // namespace gfield
