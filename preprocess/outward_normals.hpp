#pragma once
// Angle-weighted vertex normals turned outwards by the sign of the enclosed volume: the smooth
// normals of the reference tracer, which the runtime methods must shade with too.

#include <vector>

#include <glm/glm.hpp>

#include "preprocess/mesh_io.hpp"

namespace gfield {

/// +1 when the mesh's winding encloses a positive volume (outward faces), -1 otherwise
/// (meaningful for closed meshes).
double outward_orientation(const TriangleMesh& mesh);

/// V unit normals, angle-weighted over the incident faces and multiplied by
/// outward_orientation(mesh); (0,0,0) for a vertex with no non-degenerate face.
std::vector<glm::dvec3> outward_vertex_normals(const TriangleMesh& mesh);

}  // namespace gfield
