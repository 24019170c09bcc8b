// Fuzz target: one mesh format's reader (load_mesh with the surface's appearance), the format
// chosen at compile time by GFIELD_FUZZ_EXTENSION, an extension of geometry/mesh_formats.hpp
// (".gltf", ".glb": all of a glTF file's mesh primitives as one mesh, through gfield's own checks
// and then tinygltf; its extensions too: KHR_mesh_quantization, KHR_texture_transform, Draco and
// meshopt compression, the materials' mapping). A target per folder corpus/mesh_EXT.

#include <cmath>

#include "fuzz_support.hpp"
#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "gfield/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, size_t size) {
  using namespace gfield;
  const std::string path =
      fuzz::write_input(data, size, std::string("input") + GFIELD_FUZZ_EXTENSION);
  TriangleMesh mesh;
  MeshAppearance appearance;
  MeshLoadStats stats;
  std::vector<std::string> warnings;
  std::string error;
  if (!load_mesh(MeshSource{path, ""}, mesh, &appearance, warnings, error, &stats)) {
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
  const size_t faces = mesh.triangles.size();
  fuzz::check(appearance.corner_uv.empty() || appearance.corner_uv.size() == 3 * faces,
              "texture coordinates that are not one per corner");
  for (const glm::vec2& uv : appearance.corner_uv) {
    fuzz::check(std::abs(uv.x) <= kMaxTextureCoordinate && std::abs(uv.y) <= kMaxTextureCoordinate,
                "a texture coordinate out of range");
  }
  fuzz::check(appearance.face_material.empty() || appearance.face_material.size() == faces,
              "materials that are not one per face");
  for (const int m : appearance.face_material) {
    fuzz::check(m >= -1 && m < int(appearance.materials.size()), "a material out of range");
  }
  for (const std::string& w : warnings) {
    fuzz::check(w.find('\n') == std::string::npos, "a warning of more than one line");
  }
  return 0;
}
