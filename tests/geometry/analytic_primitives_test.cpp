// Analytic ray-shape intersections against the shapes' implicit inside tests: the reported hit
// is the first change of inside/outside along the ray, its normal points out, uv is in [0,1]^2.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "geometry/analytic_primitives.hpp"

namespace gfield {
namespace {

/// Inside test of each closed shape (object space).
bool inside(const Shape& s, glm::dvec3 p) {
  const double r2 = p.x * p.x + p.z * p.z;
  switch (s.type) {
    case ShapeType::kSphere:
      return glm::dot(p, p) < double(s.radius) * s.radius;
    case ShapeType::kBox:
      return std::abs(p.x) < 0.5 * s.size.x && std::abs(p.y) < 0.5 * s.size.y &&
             std::abs(p.z) < 0.5 * s.size.z;
    case ShapeType::kSlab:
      return std::abs(p.x) < 0.5 * s.size.x && std::abs(p.y) < 0.5 * s.size.y &&
             std::abs(p.z) < 0.5 * s.thickness;
    case ShapeType::kCylinder:
      return r2 < double(s.radius) * s.radius && std::abs(p.y) < 0.5 * s.height;
    case ShapeType::kHollowCylinder: {
      const double inner = double(s.radius) - double(s.thickness);
      return r2 < double(s.radius) * s.radius && r2 > inner * inner &&
             std::abs(p.y) < 0.5 * s.height;
    }
    default:
      return false;
  }
}

TEST(AnalyticPrimitives, FirstHitIsTheFirstBoundaryCrossing) {
  std::vector<Shape> shapes(5);
  shapes[0].type = ShapeType::kSphere;
  shapes[0].radius = 1.3f;
  shapes[1].type = ShapeType::kBox;
  shapes[1].size = {1.0f, 2.0f, 0.5f};
  shapes[2].type = ShapeType::kSlab;
  shapes[2].size = {2.0f, 1.5f, 0.0f};
  shapes[2].thickness = 0.2f;
  shapes[3].type = ShapeType::kCylinder;
  shapes[3].radius = 0.8f;
  shapes[3].height = 1.5f;
  shapes[4].type = ShapeType::kHollowCylinder;
  shapes[4].radius = 1.0f;
  shapes[4].thickness = 0.15f;
  shapes[4].height = 2.0f;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const Shape& shape : shapes) {
    int hits = 0;
    for (int k = 0; k < 2000; ++k) {
      // From a random point (outside or inside) towards a random point near the shape.
      const glm::dvec3 origin(3.0 * u(rng), 3.0 * u(rng), 3.0 * u(rng));
      const glm::dvec3 aim(u(rng), u(rng), u(rng));
      const glm::dvec3 d = glm::normalize(aim - origin);
      PrimitiveHit hit;
      const bool found = intersect_shape(shape, origin, d, 0.0, 1e30, hit);
      // Reference: march in small steps and find the first change of the inside test.
      const bool start = inside(shape, origin);
      double first = -1.0;
      for (double t = 1e-4; t < 8.0; t += 1e-3) {
        if (inside(shape, origin + t * d) != start) {
          first = t;
          break;
        }
      }
      if (first < 0.0) {
        // No crossing seen by the march: any hit must be a grazing one (shorter than a step).
        if (found) {
          EXPECT_FALSE(inside(shape, origin + (hit.t + 2e-3) * d) != start);
        }
        continue;
      }
      ASSERT_TRUE(found) << shape_name(shape.type) << " ray " << k;
      ++hits;
      if (hit.t < first - 1.01e-3) {
        // A sliver thinner than a march step (a corner grazed): find it with a fine march.
        bool crossed = false;
        for (double t = hit.t + 1e-8; t < hit.t + 1.01e-3 && !crossed; t += 1e-6) {
          crossed = inside(shape, origin + t * d) != start;
        }
        EXPECT_TRUE(crossed) << shape_name(shape.type) << " t " << hit.t << " march " << first;
      } else {
        EXPECT_NEAR(hit.t, first, 1.01e-3) << shape_name(shape.type);
      }
      EXPECT_NEAR(glm::length(hit.normal), 1.0, 1e-12);
      const glm::dvec3 p = origin + hit.t * d;
      EXPECT_FALSE(inside(shape, p + 1e-6 * hit.normal)) << shape_name(shape.type);
      EXPECT_TRUE(inside(shape, p - 1e-6 * hit.normal)) << shape_name(shape.type);
      EXPECT_GE(hit.uv.x, 0.0);
      EXPECT_LE(hit.uv.x, 1.0);
      EXPECT_GE(hit.uv.y, 0.0);
      EXPECT_LE(hit.uv.y, 1.0);
    }
    EXPECT_GT(hits, 200) << shape_name(shape.type);
  }
}

TEST(AnalyticPrimitives, QuadAndRange) {
  Shape quad;
  quad.type = ShapeType::kQuad;
  quad.size = {2.0f, 4.0f, 0.0f};
  PrimitiveHit hit;
  ASSERT_TRUE(intersect_shape(quad, {0.5, -1.0, 3.0}, {0.0, 0.0, -1.0}, 0.0, 1e30, hit));
  EXPECT_DOUBLE_EQ(hit.t, 3.0);
  EXPECT_DOUBLE_EQ(hit.uv.x, 0.75);
  EXPECT_DOUBLE_EQ(hit.uv.y, 0.25);
  EXPECT_FALSE(intersect_shape(quad, {1.5, 0.0, 3.0}, {0.0, 0.0, -1.0}, 0.0, 1e30, hit));
  EXPECT_FALSE(intersect_shape(quad, {0.5, 0.0, 3.0}, {0.0, 0.0, -1.0}, 0.0, 2.5, hit));  // t_max
  // t_min skips the near sphere surface: the far one is found.
  Shape sphere;
  sphere.type = ShapeType::kSphere;
  ASSERT_TRUE(intersect_shape(sphere, {0.0, 0.0, 5.0}, {0.0, 0.0, -1.0}, 4.5, 1e30, hit));
  EXPECT_DOUBLE_EQ(hit.t, 6.0);
  EXPECT_DOUBLE_EQ(hit.normal.z, -1.0);
}

}  // namespace
}  // namespace gfield
