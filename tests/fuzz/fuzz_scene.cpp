// Fuzz target: scene files (parse_scene: JSON with locations, validation, numbers in range).

#include <cmath>

#include "fuzz_support.hpp"
#include "gfield/limits.hpp"
#include "gfield/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  // Relative file names in the scene resolve against the scratch folder, which holds no meshes.
  const std::string path = (fuzz::scratch_folder() / "scene.json").string();
  Scene scene;
  std::string error;
  if (!parse_scene(std::string(reinterpret_cast<const char*>(data), size), path, scene, error)) {
    fuzz::check_error(path, error);
    return 0;
  }
  fuzz::check(scene.objects.size() <= kMaxSceneObjects && scene.lights.size() <= kMaxSceneLights,
              "too many objects or lights");
  for (const SceneObject& o : scene.objects) {
    fuzz::check(o.shape.type != ShapeType::kMesh ||
                    (o.shape.mesh >= 0 && size_t(o.shape.mesh) < scene.meshes.size()),
                "a mesh object without its mesh");
    glm::dvec3 lo, hi;
    shape_bounds(o.shape, lo, hi);
    fuzz::check(box_reach(object_to_world(o.transform), lo, hi) <= kMaxCoordinate,
                "an object out of range");
  }
  const glm::vec3 forward = scene.camera.target - scene.camera.position;
  fuzz::check(glm::length(forward) > 0.0f && std::isfinite(glm::length(forward)),
              "a degenerate camera");
  return 0;
}
