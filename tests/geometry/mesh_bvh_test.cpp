// The mesh BVH (geometry/mesh_bvh.hpp) against brute force: every triangle in exactly one leaf,
// children inside their parents, a shallow tree, and the traversal (shaders/lib/bvh_trace.glsl
// compiled for the CPU) finding the nearest hit of every ray that testing every triangle finds,
// with a fraction of the work.

#include "geometry/mesh_bvh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>

#include "geometry/mesh_io.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::ivec3> triangles;
};

Mesh load(const std::string& name) {
  TriangleMesh mesh;
  std::vector<std::string> warnings;
  std::string error;
  EXPECT_TRUE(load_mesh(MeshSource{std::string(gfield::build_paths::mesh_dir()) + "/" + name, ""},
                        mesh, nullptr, warnings, error))
      << error;
  Mesh m;
  for (const glm::dvec3& p : mesh.positions)
    m.positions.emplace_back(p);
  m.triangles = mesh.triangles;
  return m;
}

/// Every triangle tested (double precision): the nearest t in [t_min, t_max], or -1.
double brute_force_t(const Mesh& m, glm::dvec3 o, glm::dvec3 d, double t_min, double t_max,
                     int& triangle) {
  double best = -1.0;
  triangle = -1;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const glm::dvec3 p0(m.positions[size_t(m.triangles[f][0])]);
    const glm::dvec3 e1 = glm::dvec3(m.positions[size_t(m.triangles[f][1])]) - p0;
    const glm::dvec3 e2 = glm::dvec3(m.positions[size_t(m.triangles[f][2])]) - p0;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0)
      continue;
    const glm::dvec3 r = o - p0;
    const double u = glm::dot(r, p) / det;
    const glm::dvec3 q = glm::cross(r, e1);
    const double v = glm::dot(d, q) / det;
    const double t = glm::dot(e2, q) / det;
    if (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t >= t_min && t <= t_max &&
        (best < 0 || t < best)) {
      best = t;
      triangle = int(f);
    }
  }
  return best;
}

int depth(const MeshBvh& bvh, int node) {
  const BvhNode& n = bvh.nodes[size_t(node)];
  return n.count > 0 ? 1 : 1 + std::max(depth(bvh, n.first), depth(bvh, n.first + 1));
}

TEST(MeshBvh, EveryTriangleInOneLeafAndChildrenInsideTheirParents) {
  for (const char* name : {"spot.obj", "teapot.obj", "stanford-bunny.obj"}) {
    const Mesh m = load(name);
    const MeshBvh bvh = build_mesh_bvh(m.positions, m.triangles);
    std::vector<int> seen(m.triangles.size(), 0);
    for (size_t i = 0; i < bvh.nodes.size(); ++i) {
      const BvhNode& n = bvh.nodes[i];
      if (n.count > 0) {
        ASSERT_LE(n.count, kBvhMaxLeaf) << name;
        for (int s = n.first; s < n.first + n.count; ++s) {
          const glm::ivec3 t = m.triangles[size_t(bvh.order[size_t(s)])];
          seen[size_t(bvh.order[size_t(s)])]++;
          for (int c = 0; c < 3; ++c) {
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(m.positions[size_t(t[c])], n.lo)) &&
                        glm::all(glm::lessThanEqual(m.positions[size_t(t[c])], n.hi)));
          }
        }
        continue;
      }
      ASSERT_GT(n.first, int(i)) << name << ": children come after their parent";
      ASSERT_LT(n.first + 1, int(bvh.nodes.size()));
      for (int c = n.first; c <= n.first + 1; ++c) {
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(bvh.nodes[size_t(c)].lo, n.lo)) &&
                    glm::all(glm::lessThanEqual(bvh.nodes[size_t(c)].hi, n.hi)));
      }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), long(m.triangles.size())) << name;
    EXPECT_LE(depth(bvh, 0), 48) << name << ": deeper than the GPU's stack allows";
  }
}

TEST(MeshBvh, NearestHitOfEveryRayAsBruteForceWithAFractionOfTheWork) {
  const Mesh m = load("spot.obj");
  const MeshBvh bvh = build_mesh_bvh(m.positions, m.triangles);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0, agree = 0, same_triangle = 0;
  long nodes = 0;
  const int rays = 3000;
  for (int i = 0; i < rays; ++i) {
    // From a sphere around the mesh towards a point inside its bounds; every third from inside.
    const glm::vec3 target(unit(rng) * 0.4f, unit(rng) * 0.7f + 0.1f, unit(rng) * 0.8f);
    glm::vec3 origin = 3.0f * glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)));
    if (i % 3 == 0)
      origin = glm::vec3(unit(rng) * 0.2f, unit(rng) * 0.3f + 0.1f, unit(rng) * 0.3f);
    const glm::vec3 d = target - origin;
    const BvhHit h = trace_mesh_bvh(bvh, m.positions, m.triangles, origin, d, 1e-4f, 1e30f);
    int triangle = -1;
    const double t = brute_force_t(m, origin, d, 1e-4, 1e30, triangle);
    nodes += h.nodes_visited;
    hits += t >= 0.0;
    if (h.hit == (t >= 0.0) && (!h.hit || std::abs(double(h.t) - t) <= 1e-4 * t))
      ++agree;
    same_triangle += h.hit && h.triangle == triangle;
  }
  std::printf("%d rays, %d hits: %.1f nodes per ray for %zu triangles\n", rays, hits,
              double(nodes) / rays, m.triangles.size());
  EXPECT_GT(hits, rays / 3);
  EXPECT_GE(agree, rays - 3) << "a few rays through edges may differ between float and double";
  EXPECT_GE(same_triangle, hits - 3);
  EXPECT_LT(double(nodes) / rays, 0.02 * double(m.triangles.size()))
      << "nodes visited per ray: " << double(nodes) / rays;
}

TEST(MeshBvh, EmptyAndDegenerateMeshes) {
  const MeshBvh empty = build_mesh_bvh({}, {});
  EXPECT_TRUE(empty.nodes.empty());
  EXPECT_FALSE(trace_mesh_bvh(empty, {}, {}, glm::vec3(0), glm::vec3(1, 0, 0), 0, 1).hit);
  // 100 copies of one triangle (coincident centroids) and zero-area ones: a tree, no hits of the
  // degenerate ones.
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 2, 2}};
  for (int i = 0; i < 100; ++i)
    m.triangles.push_back(i % 2 ? glm::ivec3(0, 1, 2) : glm::ivec3(3, 3, 3));
  const MeshBvh bvh = build_mesh_bvh(m.positions, m.triangles);
  EXPECT_LE(depth(bvh, 0), 48);
  const BvhHit h = trace_mesh_bvh(bvh, m.positions, m.triangles, glm::vec3(0.2f, 0.2f, 1.0f),
                                  glm::vec3(0, 0, -1), 0.0f, 10.0f);
  ASSERT_TRUE(h.hit);
  EXPECT_FLOAT_EQ(h.t, 1.0f);
  EXPECT_EQ(h.triangle % 2, 1);
}

}  // namespace
}  // namespace gfield
