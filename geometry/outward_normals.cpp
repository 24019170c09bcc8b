#include "geometry/outward_normals.hpp"

#include <algorithm>
#include <cmath>

namespace gfield {

double outward_orientation(const TriangleMesh& mesh) {
  double volume = 0.0;
  for (const glm::ivec3& f : mesh.triangles) {
    volume += glm::dot(mesh.positions[size_t(f.x)],
                       glm::cross(mesh.positions[size_t(f.y)], mesh.positions[size_t(f.z)]));
  }
  return volume < 0.0 ? -1.0 : 1.0;
}

std::vector<glm::dvec3> angle_weighted_vertex_normals(const TriangleMesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.positions.size(), glm::dvec3(0.0));
  for (const glm::ivec3& f : mesh.triangles) {
    const glm::dvec3 p[3] = {mesh.positions[size_t(f.x)], mesh.positions[size_t(f.y)],
                             mesh.positions[size_t(f.z)]};
    const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
    const double len = glm::length(n);
    if (len <= 0.0) {
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
      const double la = glm::length(a), lb = glm::length(b);
      if (la <= 0.0 || lb <= 0.0) {
        continue;
      }
      const double angle = std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
      normals[size_t(f[k])] += angle * n / len;
    }
  }
  for (glm::dvec3& n : normals) {
    const double len = glm::length(n);
    n = len > 0.0 ? n / len : glm::dvec3(0.0);
  }
  return normals;
}

std::vector<glm::dvec3> outward_vertex_normals(const TriangleMesh& mesh) {
  std::vector<glm::dvec3> normals = angle_weighted_vertex_normals(mesh);
  const double orientation = outward_orientation(mesh);
  for (glm::dvec3& n : normals)
    n *= orientation;
  return normals;
}

}  // namespace gfield
