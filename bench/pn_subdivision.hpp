#pragma once
// Large smooth test meshes for the benchmarks (asset build, runtime complexity), and an OBJ
// writer for them: every triangle of a mesh split into k x k
// triangles whose new vertices lie on its curved point-normal (PN) triangle (Vlachos et al. 2001,
// a cubic patch through the corners with the corners' normals), so the result is a smooth surface
// of k^2 times the faces, as a scan of the same object would be, not a flat-faced copy.

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/mesh_io.hpp"
#include "geometry/outward_normals.hpp"
#include "preprocess/mesh_proxy.hpp"

namespace gfield {

/// The cubic PN patch of one triangle (corners p, unit normals n): its point at barycentric
/// weights w (w.x of p[0], w.y of p[1], w.z of p[2]).
inline glm::dvec3 pn_point(const std::array<glm::dvec3, 3>& p, const std::array<glm::dvec3, 3>& n,
                           glm::dvec3 w) {
  auto b = [&](int i, int j) {
    return (2.0 * p[i] + p[j] - glm::dot(p[j] - p[i], n[i]) * n[i]) / 3.0;
  };
  const glm::dvec3 b210 = b(0, 1), b120 = b(1, 0), b021 = b(1, 2), b012 = b(2, 1), b102 = b(2, 0),
                   b201 = b(0, 2);
  const glm::dvec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
  const glm::dvec3 b111 = e + (e - (p[0] + p[1] + p[2]) / 3.0) / 2.0;
  const double u = w.x, v = w.y, t = w.z;
  return p[0] * u * u * u + p[1] * v * v * v + p[2] * t * t * t + 3.0 * b210 * u * u * v +
         3.0 * b120 * u * v * v + 3.0 * b201 * u * u * t + 3.0 * b021 * v * v * t +
         3.0 * b102 * u * t * t + 3.0 * b012 * v * t * t + 6.0 * b111 * u * v * t;
}

/// `mesh` (welded first) with every triangle split into k x k on its PN patch: F k^2 faces, the
/// points of a shared edge shared (the patch's edge depends on the edge's ends only).
inline TriangleMesh pn_subdivided(const TriangleMesh& mesh, int k) {
  const TriangleMesh welded = weld_positions(mesh);
  const std::vector<glm::dvec3> normals = angle_weighted_vertex_normals(welded);
  TriangleMesh out;
  out.positions = welded.positions;
  std::unordered_map<uint64_t, int> edge_points;  // (low, high) -> first of its k - 1 points
  std::vector<int> grid(size_t((k + 1) * (k + 1)));
  for (const glm::ivec3& t : welded.triangles) {
    const std::array<glm::dvec3, 3> p{welded.positions[t[0]], welded.positions[t[1]],
                                      welded.positions[t[2]]};
    const std::array<glm::dvec3, 3> n{normals[t[0]], normals[t[1]], normals[t[2]]};
    // Grid point (i, j): weights (k - i - j, i, j) / k of corners 0, 1, 2.
    auto point = [&](int i, int j) -> int {
      const int w[3] = {k - i - j, i, j};
      int zero = -1, corners = 0;
      for (int c = 0; c < 3; ++c) {
        if (w[c] == 0)
          zero = c;
        corners += w[c] > 0;
      }
      if (corners == 1)
        return w[0] == k ? t[0] : w[1] == k ? t[1] : t[2];
      const glm::dvec3 weights(double(w[0]) / k, double(w[1]) / k, double(w[2]) / k);
      if (corners == 3) {
        out.positions.push_back(pn_point(p, n, weights));
        return int(out.positions.size()) - 1;
      }
      const int a = t[(zero + 1) % 3], b = t[(zero + 2) % 3];
      const int low = std::min(a, b), high = std::max(a, b);
      const int along = w[(a == high ? zero + 1 : zero + 2) % 3];  // steps from `low`
      const uint64_t key = (uint64_t(uint32_t(low)) << 32) | uint32_t(high);
      auto [it, inserted] = edge_points.emplace(key, int(out.positions.size()));
      if (inserted)
        out.positions.resize(out.positions.size() + size_t(k - 1), glm::dvec3(0.0));
      const int index = it->second + along - 1;
      out.positions[size_t(index)] = pn_point(p, n, weights);
      return index;
    };
    for (int i = 0; i <= k; ++i)
      for (int j = 0; i + j <= k; ++j)
        grid[size_t(i * (k + 1) + j)] = point(i, j);
    auto g = [&](int i, int j) { return grid[size_t(i * (k + 1) + j)]; };
    for (int i = 0; i < k; ++i)
      for (int j = 0; i + j < k; ++j) {
        out.triangles.push_back({g(i, j), g(i + 1, j), g(i, j + 1)});
        if (i + j < k - 1)
          out.triangles.push_back({g(i + 1, j), g(i + 1, j + 1), g(i, j + 1)});
      }
  }
  return out;
}

/// Writes `mesh` as a plain OBJ (positions and faces); false when the file cannot be written.
inline bool write_obj(const std::string& path, const TriangleMesh& mesh) {
  FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr)
    return false;
  for (const glm::dvec3& p : mesh.positions)
    std::fprintf(file, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
  for (const glm::ivec3& t : mesh.triangles)
    std::fprintf(file, "f %d %d %d\n", t[0] + 1, t[1] + 1, t[2] + 1);
  return std::fclose(file) == 0;
}

}  // namespace gfield
