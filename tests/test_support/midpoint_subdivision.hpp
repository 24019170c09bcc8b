#pragma once
// Flat-faced large meshes for tests and benchmarks: every face split into four at its sides'
// midpoints (shared between the faces of a side), so the surface stays the same, flat across
// each original face, with 4^levels times the faces (a mesh exported from a modeller's
// subdivision without smoothing, or a CAD tessellation refined for a solver).

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "geometry/mesh_io.hpp"

namespace gfield::test {

/// `mesh` split at its sides' midpoints `levels` times: F * 4^levels faces, the original
/// positions first.
inline TriangleMesh midpoint_subdivided(TriangleMesh mesh, int levels) {
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto at = [&](int a, int b) {
      const auto [it, inserted] = midpoint.emplace(std::minmax(a, b), int(mesh.positions.size()));
      if (inserted)
        mesh.positions.push_back(0.5 * (mesh.positions[size_t(a)] + mesh.positions[size_t(b)]));
      return it->second;
    };
    std::vector<glm::ivec3> faces;
    faces.reserve(4 * mesh.triangles.size());
    for (const glm::ivec3& t : mesh.triangles) {
      const int ab = at(t[0], t[1]), bc = at(t[1], t[2]), ca = at(t[2], t[0]);
      faces.insert(faces.end(), {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}});
    }
    mesh.triangles = std::move(faces);
  }
  return mesh;
}

}  // namespace gfield::test
