// Closest points on triangles and meshes against brute force: every triangle of the mesh tried,
// and every point of a fine barycentric grid of a triangle.

#include "preprocess/closest_point.hpp"

#include <gtest/gtest.h>

#include <random>

namespace gfield {
namespace {

glm::dvec3 at(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, glm::dvec2 uv) {
  return a + uv.x * (b - a) + uv.y * (c - a);
}

TEST(ClosestPoint, NoPointOfTheTriangleIsCloserThanTheOneFound) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  auto random_point = [&] { return glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  const int steps = 60;
  for (int trial = 0; trial < 300; ++trial) {
    glm::dvec3 a = random_point(), b = random_point(), c = random_point();
    if (trial % 10 == 1)
      c = a + 0.3 * (b - a);  // collinear
    if (trial % 10 == 2)
      b = c = a;  // one point
    const glm::dvec3 p = 2.0 * random_point();
    const glm::dvec2 uv = closest_barycentrics(p, a, b, c);
    ASSERT_GE(uv.x, -1e-12);
    ASSERT_GE(uv.y, -1e-12);
    ASSERT_LE(uv.x + uv.y, 1.0 + 1e-12);
    const double found = glm::length(at(a, b, c, uv) - p);
    for (int i = 0; i <= steps; ++i)
      for (int j = 0; i + j <= steps; ++j) {
        const glm::dvec2 grid(double(i) / steps, double(j) / steps);
        ASSERT_LE(found, glm::length(at(a, b, c, grid) - p) + 1e-9)
            << "trial " << trial << " grid " << i << ", " << j;
      }
  }
}

TEST(ClosestPoint, MeshQueriesFindTheNearestOfAllTriangles) {
  // A random soup of triangles in the unit cube, queried inside and around it.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  TriangleMesh mesh;
  for (int f = 0; f < 400; ++f) {
    const glm::dvec3 centre(coordinate(rng), coordinate(rng), coordinate(rng));
    for (int k = 0; k < 3; ++k)
      mesh.positions.push_back(centre +
                               0.1 * glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)));
    mesh.triangles.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  EmbreeMesh embree;
  std::string error;
  ASSERT_TRUE(embree.build(mesh, error)) << error;
  std::vector<glm::dvec3> points;
  for (int k = 0; k < 2000; ++k)
    points.push_back(glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)) * 1.4 - 0.2);
  const std::vector<ClosestPoint> found = closest_points(embree, mesh, points);
  for (size_t k = 0; k < points.size(); ++k) {
    double nearest = 1e30;
    for (const glm::ivec3& t : mesh.triangles) {
      const glm::dvec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                       &c = mesh.positions[t[2]];
      nearest = std::min(
          nearest, glm::length(at(a, b, c, closest_barycentrics(points[k], a, b, c)) - points[k]));
    }
    ASSERT_GE(found[k].triangle, 0);
    EXPECT_NEAR(found[k].distance, nearest, 1e-9) << "point " << k;
    const glm::ivec3& t = mesh.triangles[size_t(found[k].triangle)];
    const glm::dvec3 on = at(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]],
                             {found[k].u, found[k].v});
    EXPECT_NEAR(glm::length(on - points[k]), found[k].distance, 1e-12);
  }
}

TEST(ClosestPoint, AMeshWithoutTrianglesFindsNothing) {
  const TriangleMesh empty;
  const EmbreeMesh embree;  // Embree builds no BVH of nothing; the query needs none
  const std::vector<ClosestPoint> found = closest_points(embree, empty, {glm::dvec3(0.0)});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].triangle, -1);
}

}  // namespace
}  // namespace gfield
