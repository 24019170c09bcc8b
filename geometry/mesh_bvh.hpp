#pragma once
// A bounding volume hierarchy over a triangle mesh: the exact-tracing peer of the geometry
// field. Built with binned SAH (Wald 2007: 16 bins on the widest axis of the node's
// triangle centroids, traversal cost 1, triangle cost 1; leaves of at most kBvhMaxLeaf
// triangles), flattened depth first with siblings side by side, so that a node needs one index
// (the left child; the right one follows it). The same traversal runs on the CPU and the GPU
// (shaders/lib/bvh_trace.glsl). No CGAL, no Embree: gfield-view builds it at load.

#include <vector>

#include <glm/glm.hpp>

namespace gfield {

inline constexpr int kBvhMaxLeaf = 4;

/// One node: its bounds (mesh coordinates) and where its children or triangles are.
struct BvhNode {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
  int first = 0;  ///< inner node: index of its left child (the right child is first + 1);
                  ///< leaf: index of its first triangle in MeshBvh::order
  int count = 0;  ///< triangles of a leaf (1..kBvhMaxLeaf); 0 for an inner node
};

struct MeshBvh {
  std::vector<BvhNode> nodes;  ///< nodes[0] is the root (empty for a mesh without triangles)
  std::vector<int> order;      ///< F triangle indices in leaf order: leaf triangles are contiguous
};

/// Builds the BVH of `triangles` (F, indices into `positions`, V points, mesh coordinates).
/// Degenerate triangles are kept (they never hit). O(F log F).
MeshBvh build_mesh_bvh(const std::vector<glm::vec3>& positions,
                       const std::vector<glm::ivec3>& triangles);

/// The nearest hit of origin + t direction, t in [t_min, t_max], on the triangles of `bvh` (the
/// GLSL traversal, compiled for the CPU); `nodes_visited` counts the nodes whose bounds were
/// tested. triangle: the mesh's triangle index (-1: miss); u, v: barycentrics of corners 1, 2.
struct BvhHit {
  bool hit = false;
  float t = 0.0f;
  int triangle = -1;
  float u = 0.0f;
  float v = 0.0f;
  int nodes_visited = 0;
};
BvhHit trace_mesh_bvh(const MeshBvh& bvh, const std::vector<glm::vec3>& positions,
                      const std::vector<glm::ivec3>& triangles, glm::vec3 origin,
                      glm::vec3 direction, float t_min, float t_max);

}  // namespace gfield
