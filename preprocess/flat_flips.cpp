#include "preprocess/flat_flips.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "geometry/edge_key.hpp"

namespace gfield {
namespace {

/// The angle at `c` of the triangle (a, b, c), radians.
double angle_at(const glm::dvec3& c, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 u = a - c, v = b - c;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

double smallest_angle(const TriangleMesh& mesh, const glm::ivec3& t) {
  const glm::dvec3 &a = mesh.positions[size_t(t[0])], &b = mesh.positions[size_t(t[1])],
                   &c = mesh.positions[size_t(t[2])];
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

/// Each directed edge's face; -1 where two faces hold it (not a manifold, or misoriented).
struct EdgeFaces {
  std::unordered_map<uint64_t, int> face;
  void set(int u, int v, int f) { face[half_edge_key(u, v)] = f; }
  void add(int u, int v, int f) {
    const auto [it, inserted] = face.emplace(half_edge_key(u, v), f);
    if (!inserted)
      it->second = -1;
  }
  bool has(int u, int v) const { return face.count(half_edge_key(u, v)) > 0; }
  int at(int u, int v) const {
    const auto it = face.find(half_edge_key(u, v));
    return it == face.end() ? -1 : it->second;
  }
};

/// The corner of `t` after the directed edge u -> v, or -1 where t does not hold that edge.
int apex(const glm::ivec3& t, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == u && t[(k + 1) % 3] == v)
      return t[(k + 2) % 3];
  return -1;
}

/// Whether the pair of faces (a, b, c) and (b, a, d) may become (a, d, c) and (d, b, c).
bool flips(const TriangleMesh& mesh, int a, int b, int c, int d, double tolerance) {
  const glm::dvec3 &pa = mesh.positions[size_t(a)], &pb = mesh.positions[size_t(b)],
                   &pc = mesh.positions[size_t(c)], &pd = mesh.positions[size_t(d)];
  if (angle_at(pc, pa, pb) + angle_at(pd, pa, pb) <= std::numbers::pi + 1e-12)
    return false;  // locally Delaunay
  const glm::dvec3 old_normal = glm::cross(pb - pa, pc - pa) + glm::cross(pa - pb, pd - pb);
  const glm::dvec3 first = glm::cross(pd - pa, pc - pa), second = glm::cross(pb - pd, pc - pd);
  if (!(glm::dot(first, old_normal) > 0.0 && glm::dot(second, old_normal) > 0.0))
    return false;
  const double largest = std::max({glm::length(glm::cross(pb - pa, pc - pa)),
                                   glm::length(glm::cross(pb - pa, pd - pa)), glm::length(first),
                                   glm::length(second)});
  const double height = std::abs(glm::dot(pb - pa, glm::cross(pc - pa, pd - pa))) / largest;
  return height <= tolerance;
}

}  // namespace

FlatFlipsReport flip_flat_edges(TriangleMesh& mesh, double tolerance) {
  FlatFlipsReport report;
  EdgeFaces edges;
  edges.face.reserve(3 * mesh.triangles.size());
  std::vector<uint64_t> work;
  work.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles[f][k], v = mesh.triangles[f][(k + 1) % 3];
      edges.add(u, v, int(f));
      work.push_back(half_edge_key(u, v));
    }
  const size_t most = 8 * mesh.triangles.size();
  while (!work.empty() && report.flips < most) {
    const int a = half_edge_source(work.back()), b = half_edge_target(work.back());
    work.pop_back();
    const int f1 = edges.at(a, b), f2 = edges.at(b, a);
    if (f1 < 0 || f2 < 0 || f1 == f2)
      continue;
    glm::ivec3 &t1 = mesh.triangles[size_t(f1)], &t2 = mesh.triangles[size_t(f2)];
    const int c = apex(t1, a, b), d = apex(t2, b, a);
    // The quad's sides must each belong to one face (else a flip would unblock them).
    if (c < 0 || d < 0 || c == d || edges.has(c, d) || edges.has(d, c) || edges.at(a, d) != f2 ||
        edges.at(d, b) != f2 || edges.at(b, c) != f1 || edges.at(c, a) != f1 ||
        !flips(mesh, a, b, c, d, tolerance))
      continue;
    t1 = {a, d, c};
    t2 = {d, b, c};
    edges.face.erase(half_edge_key(a, b));
    edges.face.erase(half_edge_key(b, a));
    edges.set(a, d, f1);
    edges.set(d, c, f1);
    edges.set(b, c, f2);
    edges.set(c, d, f2);
    work.insert(work.end(), {half_edge_key(a, d), half_edge_key(d, b), half_edge_key(b, c),
                             half_edge_key(c, a)});
    ++report.flips;
  }
  for (const glm::ivec3& t : mesh.triangles)
    report.needles += smallest_angle(mesh, t) < 1e-4 ? 1 : 0;
  return report;
}

}  // namespace gfield
