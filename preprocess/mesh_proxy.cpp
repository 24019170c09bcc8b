#include "preprocess/mesh_proxy.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <numeric>
#include <unordered_map>
#include <vector>

#include "gfield/stopwatch.hpp"
#include "preprocess/flat_flips.hpp"

namespace gfield {
namespace {

struct PositionHash {
  size_t operator()(const glm::dvec3& p) const {
    uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < 3; ++k) {
      uint64_t bits;
      const double v = p[k] == 0.0 ? 0.0 : p[k];  // -0 and +0 weld
      std::memcpy(&bits, &v, sizeof(bits));
      h = (h ^ bits) * 1099511628211ull;
    }
    return size_t(h ^ (h >> 29));
  }
};

bool has_area(const TriangleMesh& mesh, const glm::ivec3& t) {
  const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
  return glm::length(glm::cross(b - a, c - a)) > 0.0;
}

/// Removes every copy of a face whose three vertices another face has too: the collapses leave
/// such folded pairs (a face and its reverse over one triangle), whose edges have 3 or 4 faces.
void drop_folded_pairs(std::vector<unsigned>& indices) {
  const size_t faces = indices.size() / 3;
  std::vector<std::array<unsigned, 4>> sorted(faces);  // sorted corners, face
  for (size_t f = 0; f < faces; ++f) {
    sorted[f] = {indices[3 * f], indices[3 * f + 1], indices[3 * f + 2], unsigned(f)};
    std::sort(sorted[f].begin(), sorted[f].begin() + 3);
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> folded(faces, 0);
  for (size_t k = 1; k < faces; ++k)
    if (std::equal(sorted[k].begin(), sorted[k].begin() + 3, sorted[k - 1].begin()))
      folded[sorted[k][3]] = folded[sorted[k - 1][3]] = 1;
  size_t kept = 0;
  for (size_t f = 0; f < faces; ++f)
    if (!folded[f]) {
      std::copy_n(indices.begin() + std::ptrdiff_t(3 * f), 3,
                  indices.begin() + std::ptrdiff_t(kept));
      kept += 3;
    }
  indices.resize(kept);
}

/// Union-find over vertex indices.
struct VertexSets {
  std::vector<int> parent;
  explicit VertexSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[size_t(x)] != x)
      x = parent[size_t(x)] = parent[size_t(parent[size_t(x)])];
    return x;
  }
  void unite(int a, int b) { parent[size_t(find(a))] = find(b); }
  /// The distinct sets among `members`.
  size_t count(const std::vector<int>& members) {
    std::vector<int> roots;
    for (int v : members)
      roots.push_back(find(v));
    std::sort(roots.begin(), roots.end());
    return size_t(std::unique(roots.begin(), roots.end()) - roots.begin());
  }
};

}  // namespace

long surface_genus(const TriangleMesh& mesh) {
  // Each edge (low, high) filed under its low vertex, so an edge's faces are the repeats of
  // `high` among its low vertex's few entries (linear, no hashing).
  const size_t n = mesh.positions.size();
  std::vector<size_t> first(n + 1, 0);
  auto proper = [](const glm::ivec3& t) { return t[0] != t[1] && t[1] != t[2] && t[0] != t[2]; };
  for (const glm::ivec3& t : mesh.triangles)
    if (proper(t))
      for (int k = 0; k < 3; ++k)
        ++first[size_t(std::min(t[k], t[(k + 1) % 3])) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<int> high(first[n]);
  std::vector<size_t> next(first.begin(), first.end() - 1);
  VertexSets components(n);
  std::vector<char> used(n, 0);
  long faces = 0;
  for (const glm::ivec3& t : mesh.triangles) {
    if (!proper(t))
      continue;
    ++faces;
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      high[next[size_t(std::min(a, b))]++] = std::max(a, b);
      components.unite(a, b);
      used[size_t(a)] = 1;
    }
  }
  VertexSets loops(n);
  std::vector<int> boundary, vertices;
  long edges = 0;
  for (size_t v = 0; v < n; ++v) {
    if (used[v])
      vertices.push_back(int(v));
    const auto begin = high.begin() + std::ptrdiff_t(first[v]);
    const auto end = high.begin() + std::ptrdiff_t(first[v + 1]);
    std::sort(begin, end);
    for (auto run = begin; run != end;) {
      const auto stop = std::find_if(run, end, [&](int h) { return h != *run; });
      if (stop - run > 2)
        return -1;
      if (stop - run == 1) {
        loops.unite(int(v), *run);
        boundary.push_back(int(v));
      }
      ++edges;
      run = stop;
    }
  }
  const long chi = long(vertices.size()) - edges + faces;
  const long c = long(components.count(vertices)), b = long(loops.count(boundary));
  return std::max(0L, (2 * c - chi - b) / 2);
}

TriangleMesh weld_positions(const TriangleMesh& mesh) {
  TriangleMesh welded;
  std::unordered_map<glm::dvec3, int, PositionHash> index;
  index.reserve(mesh.positions.size());
  std::vector<int> to(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    auto [it, inserted] = index.emplace(mesh.positions[v], int(welded.positions.size()));
    if (inserted)
      welded.positions.push_back(mesh.positions[v]);
    to[v] = it->second;
  }
  welded.triangles.reserve(mesh.triangles.size());
  for (const glm::ivec3& t : mesh.triangles)
    welded.triangles.push_back({to[size_t(t[0])], to[size_t(t[1])], to[size_t(t[2])]});
  return welded;
}

bool make_mesh_proxy(const TriangleMesh& input, size_t target_faces, MeshProxy& out,
                     std::string& error) {
  Stopwatch watch;
  out = {};
  out.welded = weld_positions(input);
  const TriangleMesh& welded = out.welded;
  out.genus = surface_genus(welded);
  std::vector<unsigned> indices;
  indices.reserve(3 * welded.triangles.size());
  for (const glm::ivec3& t : welded.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2] && has_area(welded, t))
      indices.insert(indices.end(), {unsigned(t[0]), unsigned(t[1]), unsigned(t[2])});
  if (indices.empty()) {
    error = "no face with a positive area (the mesh is degenerate: zero area or collinear points)";
    return false;
  }
  std::vector<float> positions(3 * welded.positions.size());
  for (size_t v = 0; v < welded.positions.size(); ++v)
    for (int k = 0; k < 3; ++k)
      positions[3 * v + size_t(k)] = float(welded.positions[v][k]);
  std::vector<unsigned> simplified(indices.size());
  float relative_error = 0.0f;
  // An error bound of 1 (the mesh's extent) lets the face count alone stop the collapses.
  const size_t count = meshopt_simplify(
      simplified.data(), indices.data(), indices.size(), positions.data(), welded.positions.size(),
      3 * sizeof(float), 3 * target_faces, 1.0f, meshopt_SimplifyLockBorder, &relative_error);
  const double scale =
      double(meshopt_simplifyScale(positions.data(), welded.positions.size(), 3 * sizeof(float)));
  out.error = double(relative_error) * scale;
  simplified.resize(count);
  drop_folded_pairs(simplified);
  std::vector<int> compact(welded.positions.size(), -1);
  for (size_t i = 0; i < simplified.size(); i += 3) {
    glm::ivec3 t;
    for (int k = 0; k < 3; ++k) {
      int& v = compact[simplified[i + size_t(k)]];
      if (v < 0) {
        v = int(out.proxy.positions.size());
        out.proxy.positions.push_back(welded.positions[simplified[i + size_t(k)]]);
      }
      t[k] = v;
    }
    out.proxy.triangles.push_back(t);
  }
  // Collapses on flat parts leave needles (three collinear corners); flips within a tenth of
  // the error bound remove them.
  out.flat_flips = flip_flat_edges(out.proxy, 0.1 * out.error + 1e-7 * scale).flips;
  out.seconds = watch.seconds();
  return true;
}

}  // namespace gfield
