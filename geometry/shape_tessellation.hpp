#pragma once
// Analytic shapes as triangle meshes, for `gfield export-gltf` (gltf_writer.hpp): the sphere,
// box, cylinder, slab and hollow cylinder of a scene (object space, centred on the origin, as
// analytic_primitives.hpp intersects them), with the texture coordinates of docs/scenes.md
// ("Texture coordinates") at every corner. Vertices lie on the exact surface; a smooth surface
// shares its vertices (the angle-weighted vertex normals of the reference tracer come out as the
// surface's normals: radial on spheres and cylinder walls), a sharp edge separates them (a box's
// faces, a cylinder's caps and wall stay flat). Triangles wind counter-clockwise seen from
// outside (a hollow cylinder's inner wall faces its axis). Quads are exported by the writer.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "gfield/scene.hpp"

namespace gfield {

/// A tessellated shape: `mesh` and one texture coordinate per triangle corner (u, v in gfield's
/// convention, v up), 3 per triangle in the order of mesh.triangles.
struct TessellatedShape {
  TriangleMesh mesh;
  std::vector<glm::vec2> corner_uv;
};

/// Smallest number of segments around a round shape (`segments`), and the largest.
inline constexpr int kMinShapeSegments = 8;
inline constexpr int kMaxShapeSegments = 4096;

/// `shape` (kSphere, kBox, kCylinder, kSlab, kHollowCylinder) with `segments` segments around the
/// Y axis (spheres: segments / 2 rings from pole to pole; boxes and slabs: two triangles per
/// face). `segments` in [kMinShapeSegments, kMaxShapeSegments]; another shape type gives an empty
/// mesh.
TessellatedShape tessellate_shape(const Shape& shape, int segments);

}  // namespace gfield
