// Fuzz target: one mesh format's reader (load_mesh), the format chosen at compile time by
// GFIELD_FUZZ_EXTENSION (".obj", ".ply", ".off", ".stl", ".gltf", ".glb": all of a glTF file's
// mesh primitives as one mesh, through gfield's own checks and then tinygltf).

#include <cmath>

#include "fuzz_support.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path =
      fuzz::write_input(data, size, std::string("input") + GFIELD_FUZZ_EXTENSION);
  TriangleMesh mesh;
  MeshLoadStats stats;
  std::string error;
  if (!load_mesh(path, mesh, error, &stats)) {
    fuzz::check_error(path, error);
    return 0;
  }
  fuzz::check(!mesh.triangles.empty() && stats.polygons > 0, "a mesh without faces");
  for (const glm::dvec3& p : mesh.positions) {
    for (int k = 0; k < 3; ++k) {
      fuzz::check(std::abs(p[k]) <= kMaxCoordinate, "a coordinate out of range");
    }
  }
  for (const glm::ivec3& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      fuzz::check(t[k] >= 0 && size_t(t[k]) < mesh.positions.size(), "an index out of range");
    }
  }
  return 0;
}
