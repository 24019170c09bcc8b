#pragma once
// Angle-weighted vertex normals, and the same turned outwards by the sign of the enclosed volume:
// the smooth normals of the reference tracer, which the geometry image samples and the runtime
// methods shade with too.

#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// +1 when the mesh's winding encloses a positive volume (outward faces), -1 otherwise
/// (meaningful for closed meshes).
double outward_orientation(const TriangleMesh& mesh);

/// V unit normals, the mean of the incident faces' normals weighted by the face's angle at the
/// vertex, oriented as the faces are wound; (0,0,0) for a vertex with no non-degenerate face.
std::vector<glm::dvec3> angle_weighted_vertex_normals(const TriangleMesh& mesh);

/// angle_weighted_vertex_normals(mesh) multiplied by outward_orientation(mesh).
std::vector<glm::dvec3> outward_vertex_normals(const TriangleMesh& mesh);

}  // namespace gfield
