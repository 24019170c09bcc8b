// Edge flips where a mesh is flat (flat_flips.hpp): a needle with three collinear corners is
// flipped away without moving the surface, a bent pair beyond the tolerance and an edge of three
// faces are left alone, and faces keep their orientation.

#include "preprocess/flat_flips.hpp"

#include <gtest/gtest.h>

namespace gfield {
namespace {

glm::dvec3 face_normal(const TriangleMesh& mesh, const glm::ivec3& t) {
  const std::vector<glm::dvec3>& p = mesh.positions;
  return glm::cross(p[size_t(t[1])] - p[size_t(t[0])], p[size_t(t[2])] - p[size_t(t[0])]);
}

double area(const TriangleMesh& mesh) {
  double sum = 0.0;
  for (const glm::ivec3& t : mesh.triangles)
    sum += 0.5 * glm::length(face_normal(mesh, t));
  return sum;
}

/// The square [0,2]x[0,1] in z = 0 with vertex 4 on its bottom side's middle, fanned so that face
/// (0, 4, 1) is a needle: its three corners lie on one line.
TriangleMesh square_with_needle() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, {1, 0, 0}};
  mesh.triangles = {{0, 4, 1}, {0, 1, 2}, {0, 2, 3}};
  return mesh;
}

TEST(FlatFlips, ANeedleIsFlippedAwayAndTheSurfaceStays) {
  TriangleMesh mesh = square_with_needle();
  const double before = area(mesh);
  const FlatFlipsReport report = flip_flat_edges(mesh, 1e-9);
  EXPECT_GE(report.flips, 1u);
  EXPECT_EQ(report.needles, 0u);
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.positions, square_with_needle().positions);
  EXPECT_NEAR(area(mesh), before, 1e-12);
  for (const glm::ivec3& t : mesh.triangles) {
    const glm::dvec3 n = face_normal(mesh, t);
    EXPECT_GT(glm::length(n), 0.1);  // no face of zero area is left
    EXPECT_GT(n.z, 0.0);             // and each keeps facing +z
  }
}

TEST(FlatFlips, ANeedleOnTheBorderStaysAndIsCounted) {
  // The needle's long side (0, 1) is the border; its other sides are locally Delaunay.
  TriangleMesh mesh = square_with_needle();
  mesh.triangles = {{0, 4, 1}, {1, 4, 2}};
  const TriangleMesh before = mesh;
  const FlatFlipsReport report = flip_flat_edges(mesh, 1e-9);
  EXPECT_EQ(report.flips, 0u);
  EXPECT_EQ(report.needles, 1u);
  EXPECT_EQ(mesh.triangles, before.triangles);
}

TEST(FlatFlips, ABentPairIsLeftAloneUnlessTheToleranceAllowsIt) {
  // Two faces over the diagonal (0, 2) of a unit square whose corner 3 is lifted by 0.1: not
  // locally Delaunay (the opposite angles are near 90 degrees but the pair is a long thin quad).
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {4, 0, 0}, {4.2, 1, 0.1}, {0.2, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  TriangleMesh bent = mesh;
  EXPECT_EQ(flip_flat_edges(bent, 1e-3).flips, 0u);
  EXPECT_EQ(bent.triangles, mesh.triangles);
  EXPECT_EQ(flip_flat_edges(bent, 0.2).flips, 1u);
}

TEST(FlatFlips, AnEdgeOfThreeFacesIsNotFlipped) {
  TriangleMesh mesh = square_with_needle();
  mesh.positions.push_back({1, -1, 0});
  mesh.triangles.push_back({0, 1, 5});  // a third face on the edge (0, 1)
  const TriangleMesh before = mesh;
  flip_flat_edges(mesh, 1e-9);
  EXPECT_EQ(mesh.triangles[1], before.triangles[1]);
}

}  // namespace
}  // namespace gfield
