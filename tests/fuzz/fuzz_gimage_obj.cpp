// Fuzz target: parameterised meshes (load_parameterized_mesh on NAME.gimage.obj).

#include <cmath>

#include "fuzz_support.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path = fuzz::write_input(data, size, "input.gimage.obj");
  ParameterizedMesh pm;
  std::string error;
  if (!load_parameterized_mesh(path, pm, error)) {
    fuzz::check_error(path, error);
    return 0;
  }
  fuzz::check(!pm.mesh.triangles.empty() && pm.corner_uv.size() == 3 * pm.mesh.triangles.size(),
              "corner uvs do not match the triangles");
  for (const glm::ivec3& t : pm.mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      fuzz::check(t[k] >= 0 && size_t(t[k]) < pm.mesh.positions.size(), "an index out of range");
    }
  }
  for (const glm::vec2 uv : pm.corner_uv) {
    fuzz::check(uv.x >= -1.0f && uv.x <= 2.0f && uv.y >= -1.0f && uv.y <= 2.0f,
                "a uv out of range");
  }
  for (const glm::dvec3& p : pm.mesh.positions) {
    for (int k = 0; k < 3; ++k) {
      fuzz::check(std::abs(p[k]) <= kMaxAssetCoordinate, "a coordinate out of range");
    }
  }
  return 0;
}
