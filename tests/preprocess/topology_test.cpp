#include "preprocess/topology.hpp"
#include "test_support/build_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace gfield {
namespace {

/// The topology of data/meshes/NAME into `report`; false (with a failure recorded) when the mesh
/// does not load.
bool bundled_topology(const std::string& name, TopologyReport& report) {
  TriangleMesh mesh;
  std::string error;
  if (!load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/" + name, mesh, error)) {
    ADD_FAILURE() << error;
    return false;
  }
  report = analyze_topology(mesh);
  return true;
}

// An m x n grid torus: V = mn, E = 3mn, F = 2mn, so chi = 0 and genus 1.
TriangleMesh grid_torus(int m, int n) {
  TriangleMesh mesh;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = 2 * M_PI * i / m, v = 2 * M_PI * j / n;
      mesh.positions.push_back(
          {(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  }
  const auto at = [&](int i, int j) { return ((i + m) % m) * n + (j + n) % n; };
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j < n; ++j) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

TEST(Topology, GridTorusHasGenusOne) {
  const TopologyReport r = analyze_topology(grid_torus(12, 8));
  ASSERT_EQ(r.components.size(), 1u);
  EXPECT_EQ(r.vertices, 96u);
  EXPECT_EQ(r.edges, 288u);
  EXPECT_EQ(r.faces, 192u);
  EXPECT_EQ(r.euler_characteristic, 0);
  EXPECT_EQ(r.components[0].genus, 1);
  EXPECT_TRUE(r.closed());
  EXPECT_TRUE(r.manifold());
}

TEST(Topology, FindsNonManifoldEdgesPinchedVerticesAndDegenerateFaces) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0},  {0, 1, 0},   {0, -1, 0},
                    {0, 0, 1}, {-1, 0, 0}, {-1, -1, 0}, {2, 0, 0}};
  // Three triangles on the edge (0, 1): a non-manifold edge.
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  TopologyReport r = analyze_topology(mesh);
  EXPECT_EQ(r.non_manifold_edges, 1u);
  EXPECT_EQ(r.components[0].genus, -1);
  // Two triangles touching at vertex 0 only (a bow tie): one pinched vertex, two disks.
  mesh.triangles = {{0, 1, 2}, {0, 5, 6}};
  r = analyze_topology(mesh);
  EXPECT_EQ(r.non_manifold_edges, 0u);
  EXPECT_EQ(r.non_manifold_vertices, 1u);
  EXPECT_EQ(r.boundary_loops, 2u);
  EXPECT_EQ(r.components.size(), 2u);
  // A repeated corner and a zero-area (collinear) triangle are degenerate.
  mesh.triangles = {{0, 1, 2}, {0, 0, 1}, {0, 1, 7}};
  r = analyze_topology(mesh);
  EXPECT_EQ(r.degenerate_faces, 2u);
  EXPECT_EQ(r.unreferenced_vertices, 4u);
}

TEST(Topology, FlippedFaceBreaksOrientation) {
  TriangleMesh mesh = grid_torus(6, 6);
  std::swap(mesh.triangles[5].y, mesh.triangles[5].z);
  const TopologyReport r = analyze_topology(mesh);
  EXPECT_FALSE(r.components[0].oriented);
  EXPECT_EQ(r.components[0].genus, -1);
}

// Figures checked by hand from the vertex and face counts (SOURCES.md): a closed triangle mesh
// has E = 3F/2, so chi = V - F/2; genus = (2 - chi - loops) / 2.
TEST(Topology, SharedMeshes) {
  {
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("spot.obj", r));  // 2930 - 5856/2 = 2: a sphere
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.euler_characteristic, 2);
    EXPECT_EQ(r.components[0].genus, 0);
  }
  {
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("rocker-arm.obj", r));  // 10044 - 20088/2 = 0: a torus
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.euler_characteristic, 0);
    EXPECT_EQ(r.components[0].genus, 1);
  }
  {
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("homer.obj", r));  // 6002 - 12000/2 = 2
    EXPECT_EQ(r.components[0].genus, 0);
    EXPECT_TRUE(r.closed());
  }
  {
    // The scan: open at the base, 5 holes (DESIGN.md), 1113 vertices never referenced.
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("stanford-bunny.obj", r));
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_EQ(r.boundary_loops, 5u);
    EXPECT_EQ(r.unreferenced_vertices, 35947u - 34834u);
    EXPECT_EQ(r.components[0].genus, 0);
    EXPECT_EQ(r.euler_characteristic, 2 - 5);
  }
  {
    // 5804 faces, 2903 vertices: closed with chi 1 unless one vertex is split: the cow has one
    // pinched vertex where two sheets touch; split, it is a sphere.
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("cow.obj", r));
    EXPECT_TRUE(r.closed());
    EXPECT_EQ(r.non_manifold_vertices, 1u);
    EXPECT_EQ(r.components[0].genus, 0);
  }
  {
    // Quads, triangulated; a head with one non-manifold edge and two separate eyes.
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("suzanne.obj", r));
    EXPECT_EQ(r.components.size(), 3u);
    EXPECT_EQ(r.non_manifold_edges, 1u);
  }
  {
    // Newell's patches with unwelded seams: many open pieces.
    TopologyReport r;
    ASSERT_TRUE(bundled_topology("teapot.obj", r));
    EXPECT_GT(r.components.size(), 1u);
    EXPECT_GT(r.boundary_loops, 0u);
    EXPECT_GT(r.duplicate_positions, 0u);
  }
}

TEST(Topology, JsonHasTheReportedFields) {
  const nlohmann::json j = topology_to_json(analyze_topology(grid_torus(5, 5)));
  EXPECT_EQ(j["components"][0]["genus"], 1);
  EXPECT_EQ(j["faces"], 50);
  EXPECT_EQ(j["closed"], true);
  EXPECT_TRUE(j.contains("bounds"));
}

}  // namespace
}  // namespace gfield
