#pragma once
// The base colour of a mesh (mesh_appearance.hpp) at points of its repaired copy, the mesh a
// geometry image is rasterised from: a repaired face that came from an input face (same corner
// positions, maybe in another order: RepairedMesh::source_face) maps its barycentric weights to
// that face's, so a texel's centre and footprint (its barycentric derivatives along the image's
// two axes) map to the input's texture coordinates. Faces that fill holes have none.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"

namespace gfield {

class AlbedoSource {
 public:
  /// `input` and its `appearance` as read; `repaired` with `source_face` (one per face of
  /// `repaired`). The references must outlive this object.
  AlbedoSource(const TriangleMesh& input, const MeshAppearance& appearance,
               const TriangleMesh& repaired, const std::vector<int>& source_face);

  /// The albedo at weights `w` of repaired face `face`, the texture averaged over the footprint
  /// whose corners' weights change by `dw_di` and `dw_dj` per texel along the image's axes
  /// (footprint_color). False for a face with no input face.
  bool sample(int face, glm::dvec3 w, glm::dvec3 dw_di, glm::dvec3 dw_dj, glm::vec3& color) const;

 private:
  const TriangleMesh& input_;
  const MeshAppearance& appearance_;
  std::vector<int> source_;          ///< input face per repaired face, -1: none
  std::vector<glm::ivec3> corners_;  ///< per repaired face: the input corner of each corner
};

}  // namespace gfield
