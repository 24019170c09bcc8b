#include "geometry/mesh_bvh.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

using namespace gfield::glsl;  // the GLSL vocabulary of bvh_trace.glsl

constexpr int kBins = 16;
/// Below this depth the SAH chooses the split; at it the median along the widest axis does, so
/// that the GPU's stack of GB_STACK_SIZE (64) far children never fills.
constexpr int kMaxSahDepth = 40;

struct Bounds {
  vec3 lo{std::numeric_limits<float>::max()};
  vec3 hi{-std::numeric_limits<float>::max()};
  void grow(vec3 p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void grow(const Bounds& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  float area() const {
    const vec3 e = max(hi - lo, vec3(0.0f));
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

/// A node's triangles: order[begin, end).
struct Range {
  int node;
  int begin;
  int end;
  int depth;
};

/// The triangle bounds and centroids the build sorts by.
struct Prims {
  std::vector<Bounds> bounds;
  std::vector<vec3> centroid;
};

Prims triangle_prims(const std::vector<vec3>& positions, const std::vector<ivec3>& triangles) {
  Prims p;
  p.bounds.resize(triangles.size());
  p.centroid.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int c = 0; c < 3; ++c)
      p.bounds[t].grow(positions[size_t(triangles[t][c])]);
    p.centroid[t] = 0.5f * (p.bounds[t].lo + p.bounds[t].hi);
  }
  return p;
}

/// The bin (0..kBins-1) of triangle t along `axis` of centroid bounds starting at c_lo, kBins
/// bins per `scale` inverse units.
int bin_of(const Prims& p, int t, int axis, float c_lo, float scale) {
  return std::clamp(int((p.centroid[size_t(t)][axis] - c_lo) * scale), 0, kBins - 1);
}

/// The SAH's best split of `r` along `axis` (bins from c_lo, `scale` as bin_of): the first bin of
/// the right side (0: no split better than a leaf of these triangles).
int best_bin(const Prims& p, const std::vector<int>& order, const Range& r, int axis, float c_lo,
             float scale, float node_area) {
  std::array<Bounds, kBins> bins;
  std::array<int, kBins> counts{};
  for (int i = r.begin; i < r.end; ++i) {
    const int t = order[size_t(i)];
    const int b = bin_of(p, t, axis, c_lo, scale);
    bins[size_t(b)].grow(p.bounds[size_t(t)]);
    counts[size_t(b)]++;
  }
  std::array<float, kBins> right_cost{};
  Bounds right;
  int right_count = 0;
  for (int b = kBins - 1; b > 0; --b) {
    right.grow(bins[size_t(b)]);
    right_count += counts[size_t(b)];
    right_cost[size_t(b)] = right.area() * float(right_count);
  }
  Bounds left;
  int left_count = 0, best = 0;
  float best_cost = float(r.end - r.begin);  // the leaf's: one test per triangle
  for (int b = 1; b < kBins; ++b) {
    left.grow(bins[size_t(b - 1)]);
    left_count += counts[size_t(b - 1)];
    if (left_count == 0 || left_count == r.end - r.begin)
      continue;
    const float cost = 1.0f + (left.area() * float(left_count) + right_cost[size_t(b)]) / node_area;
    if (cost < best_cost) {
      best_cost = cost;
      best = b;
    }
  }
  return best;
}

/// Splits r into two non-empty halves of order (the SAH's, else the median's); returns the
/// first index of the right half, or r.begin when r stays a leaf.
int split(const Prims& p, std::vector<int>& order, const Range& r, const Bounds& node) {
  Bounds c;
  for (int i = r.begin; i < r.end; ++i)
    c.grow(p.centroid[size_t(order[size_t(i)])]);
  const vec3 extent = c.hi - c.lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const int count = r.end - r.begin;
  const auto first = order.begin() + r.begin, last = order.begin() + r.end;
  if (extent[axis] > 0.0f && r.depth < kMaxSahDepth) {
    const float scale = float(kBins) / extent[axis];
    const int bin = best_bin(p, order, r, axis, c.lo[axis], scale, node.area());
    if (bin == 0 && count <= kBvhMaxLeaf)
      return r.begin;
    if (bin > 0) {
      const auto middle = std::partition(
          first, last, [&](int t) { return bin_of(p, t, axis, c.lo[axis], scale) < bin; });
      return int(middle - order.begin());  // both sides hold triangles (best_bin's counts)
    }
  }
  if (count <= kBvhMaxLeaf)
    return r.begin;
  const auto middle = first + count / 2;  // the median (also for coincident centroids)
  std::nth_element(first, middle, last, [&](int a, int b) {
    return p.centroid[size_t(a)][axis] < p.centroid[size_t(b)][axis];
  });
  return int(middle - order.begin());
}

/// shaders/lib/bvh_trace.glsl compiled as C++ over a MeshBvh.
struct GlslBvhTrace {
  const MeshBvh& bvh;
  const std::vector<vec3>& positions;
  const std::vector<ivec3>& triangles;

  vec3 gb_node_lo(int i) const { return bvh.nodes[size_t(i)].lo; }
  vec3 gb_node_hi(int i) const { return bvh.nodes[size_t(i)].hi; }
  int gb_node_first(int i) const { return bvh.nodes[size_t(i)].first; }
  int gb_node_count(int i) const { return bvh.nodes[size_t(i)].count; }
  vec3 corner(int s, int c) const {
    return positions[size_t(triangles[size_t(bvh.order[size_t(s)])][c])];
  }
  vec3 gb_triangle_p0(int s) const { return corner(s, 0); }
  vec3 gb_triangle_e1(int s) const { return corner(s, 1) - corner(s, 0); }
  vec3 gb_triangle_e2(int s) const { return corner(s, 2) - corner(s, 0); }

#include "gfield/glsl_begin.hpp"

#include "../shaders/lib/bvh_trace.glsl"

#include "gfield/glsl_end.hpp"
};

}  // namespace

MeshBvh build_mesh_bvh(const std::vector<vec3>& positions, const std::vector<ivec3>& triangles) {
  MeshBvh bvh;
  if (triangles.empty())
    return bvh;
  const Prims prims = triangle_prims(positions, triangles);
  bvh.order.resize(triangles.size());
  for (size_t t = 0; t < triangles.size(); ++t)
    bvh.order[t] = int(t);
  bvh.nodes.reserve(2 * triangles.size());
  bvh.nodes.emplace_back();
  std::vector<Range> pending = {{0, 0, int(triangles.size()), 0}};
  while (!pending.empty()) {
    const Range r = pending.back();
    pending.pop_back();
    Bounds node;
    for (int i = r.begin; i < r.end; ++i)
      node.grow(prims.bounds[size_t(bvh.order[size_t(i)])]);
    bvh.nodes[size_t(r.node)].lo = node.lo;
    bvh.nodes[size_t(r.node)].hi = node.hi;
    const int middle = split(prims, bvh.order, r, node);
    if (middle == r.begin) {
      bvh.nodes[size_t(r.node)].first = r.begin;
      bvh.nodes[size_t(r.node)].count = r.end - r.begin;
      continue;
    }
    const int left = int(bvh.nodes.size());
    bvh.nodes[size_t(r.node)].first = left;
    bvh.nodes.resize(bvh.nodes.size() + 2);
    pending.push_back({left + 1, middle, r.end, r.depth + 1});
    pending.push_back({left, r.begin, middle, r.depth + 1});
  }
  return bvh;
}

BvhHit trace_mesh_bvh(const MeshBvh& bvh, const std::vector<vec3>& positions,
                      const std::vector<ivec3>& triangles, vec3 origin, vec3 direction, float t_min,
                      float t_max) {
  BvhHit hit;
  if (bvh.nodes.empty())
    return hit;
  GlslBvhTrace trace{bvh, positions, triangles};
  const GlslBvhTrace::GbHit h = trace.gb_trace(0, origin, direction, t_min, t_max);
  hit.nodes_visited = h.nodes;
  if (h.hit) {
    hit.hit = true;
    hit.t = h.t;
    hit.triangle = bvh.order[size_t(h.slot)];
    hit.u = h.bary.x;
    hit.v = h.bary.y;
  }
  return hit;
}

}  // namespace gfield
