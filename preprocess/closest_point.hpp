#pragma once
// Closest points on a triangle mesh (Embree point queries over its BVH, in parallel): the
// distance measurements of the geometry image and the projection of a proxy's texels onto the
// full-resolution surface.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "preprocess/embree_mesh.hpp"

namespace gfield {

/// The closest point of a mesh to a query point: the triangle, the point's barycentrics there
/// (point = (1-u-v) p0 + u p1 + v p2) and its distance (mesh units). triangle = -1 when the mesh
/// has no triangle.
struct ClosestPoint {
  int triangle = -1;
  double u = 0.0;
  double v = 0.0;
  double distance = 0.0;
};

/// The closest point of triangle a, b, c to p (double precision; degenerate triangles included),
/// as barycentrics (u, v) of b and c.
glm::dvec2 closest_barycentrics(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                const glm::dvec3& c);

/// The closest point of `mesh` to `point`; `embree` holds the BVH of `mesh` (none needed when it
/// has no triangle).
ClosestPoint closest_point(const EmbreeMesh& embree, const TriangleMesh& mesh,
                           const glm::dvec3& point);

/// The closest point of `mesh` to each of `points` (P in, P out), in parallel. `embree` holds the
/// BVH of `mesh` (EmbreeMesh::build); distances are exact in double on the mesh's double positions.
std::vector<ClosestPoint> closest_points(const EmbreeMesh& embree, const TriangleMesh& mesh,
                                         const std::vector<glm::dvec3>& points);

}  // namespace gfield
