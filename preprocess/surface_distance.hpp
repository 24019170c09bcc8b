#pragma once
// Distances between surfaces for the geometry-image reconstruction error: area-weighted random
// points on one triangle mesh and their distances to the closest point of another (Embree point
// queries).

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"

namespace gfield {

/// `count` points on the triangles of `mesh`, triangles chosen with probability proportional to
/// their area and points uniform inside them (fixed `seed`: the same points on every platform
/// with the same standard library). Empty if the mesh has no area.
std::vector<glm::dvec3> sample_surface(const TriangleMesh& mesh, size_t count, uint64_t seed);

/// Distance from each point to the closest point on the triangles of `surface` (mesh units).
std::vector<double> distances_to_surface(const std::vector<glm::dvec3>& points,
                                         const TriangleMesh& surface);

}  // namespace gfield
