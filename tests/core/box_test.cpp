#include "gfield/box.hpp"

#include <gtest/gtest.h>

#include <random>

namespace gfield {
namespace {

TEST(SampleIndex, RoundTripsEveryIndex) {
  for (const int n : {1, 4, 24}) {
    for (int k = 0; k < sample_count(n); ++k) {
      const FaceSample s = face_sample(k, n);
      ASSERT_GE(s.face, 0);
      ASSERT_LT(s.face, 6);
      ASSERT_EQ(sample_index(s, n), k);
    }
  }
}

TEST(SampleIndex, FollowsTheFormatLayout) {
  // DESIGN.md: k = face * N^2 + b * N + a; on X faces (a, b) index (y, z), on Y faces (x, z),
  // on Z faces (x, y); faces -X, +X, -Y, +Y, -Z, +Z.
  const int n = 24;
  EXPECT_EQ(sample_index({kPosY, 3, 5}, n), 3 * 576 + 5 * 24 + 3);
  const glm::vec3 p = sample_point({kPosY, 3, 5}, n);
  EXPECT_FLOAT_EQ(p.x, 3.5f / 24);
  EXPECT_FLOAT_EQ(p.y, 1.0f);
  EXPECT_FLOAT_EQ(p.z, 5.5f / 24);
  const glm::vec3 q = sample_point({kNegX, 0, 23}, n);
  EXPECT_FLOAT_EQ(q.x, 0.0f);
  EXPECT_FLOAT_EQ(q.y, 0.5f / 24);
  EXPECT_FLOAT_EQ(q.z, 23.5f / 24);
  const glm::vec3 r = sample_point({kNegZ, 7, 2}, n);
  EXPECT_FLOAT_EQ(r.x, 7.5f / 24);
  EXPECT_FLOAT_EQ(r.y, 2.5f / 24);
  EXPECT_FLOAT_EQ(r.z, 0.0f);
}

TEST(SampleIndex, SamplePointMapsBackToItsSample) {
  const int n = 24;
  for (int k = 0; k < sample_count(n); ++k) {
    const FaceSample s = face_sample(k, n);
    const glm::vec3 p = sample_point(s, n);
    const glm::vec2 c = sample_coords(face_coords(s.face, p), n);
    EXPECT_NEAR(c.x, float(s.a), 1e-4f);
    EXPECT_NEAR(c.y, float(s.b), 1e-4f);
    const FaceSample back = nearest_sample(s.face, face_coords(s.face, p), n);
    EXPECT_EQ(sample_index(back, n), k);
  }
}

TEST(UnitCube, MeshCoordinatesRoundTrip) {
  const Box box{{-2.0f, 1.0f, 0.5f}, {3.0f, 2.0f, 4.0f}};
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 p{u(rng), u(rng), u(rng)};
    const glm::vec3 back = from_unit_cube(box, to_unit_cube(box, p));
    EXPECT_NEAR(glm::length(back - p), 0.0f, 1e-5f);
  }
  EXPECT_FLOAT_EQ(to_unit_cube(box, box.min).x, 0.0f);
  EXPECT_FLOAT_EQ(to_unit_cube(box, box.max).z, 1.0f);
  EXPECT_NEAR(diagonal(box), std::sqrt(25.0f + 1.0f + 12.25f), 1e-5f);
}

TEST(UnitCube, RayEntryAndExitRoundTripThroughFaceCoordinates) {
  // A ray from a point on one face to a point on another, in mesh coordinates, must clip to
  // exactly those two points, on those faces, at those face coordinates.
  const Box box{{-1.0f, -1.0f, -1.0f}, {2.0f, 3.0f, 1.0f}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.02f, 0.98f);
  std::uniform_int_distribution<int> face(0, 5);
  int tested = 0;
  while (tested < 2000) {
    const int f0 = face(rng);
    const int f1 = face(rng);
    if (f0 == f1) {
      continue;
    }
    const glm::vec2 st0{u(rng), u(rng)}, st1{u(rng), u(rng)};
    const glm::vec3 a = from_unit_cube(box, face_point(f0, st0));
    const glm::vec3 b = from_unit_cube(box, face_point(f1, st1));
    // Start outside the box, behind the entry point.
    const glm::vec3 dir = b - a;
    const glm::vec3 origin = a - 0.7f * dir;
    const CubeCrossing c =
        clip_to_unit_cube(to_unit_cube(box, origin), direction_to_unit_cube(box, dir));
    ASSERT_TRUE(c.hit);
    if (c.entry_face != f0 || c.exit_face != f1) {
      continue;  // the segment grazes an edge: another face ties; skip such rays
    }
    EXPECT_NEAR(c.t_entry, 0.7f, 1e-4f);
    EXPECT_NEAR(c.t_exit, 1.7f, 1e-4f);
    EXPECT_NEAR(glm::length(face_coords(f0, c.entry) - st0), 0.0f, 1e-4f);
    EXPECT_NEAR(glm::length(face_coords(f1, c.exit) - st1), 0.0f, 1e-4f);
    ++tested;
  }
}

TEST(UnitCube, RayStartingInsideHasNegativeEntry) {
  const CubeCrossing c = clip_to_unit_cube({0.5f, 0.5f, 0.5f}, {1.0f, 0.0f, 0.0f});
  ASSERT_TRUE(c.hit);
  EXPECT_FLOAT_EQ(c.t_entry, -0.5f);
  EXPECT_FLOAT_EQ(c.t_exit, 0.5f);
  EXPECT_EQ(c.entry_face, kNegX);
  EXPECT_EQ(c.exit_face, kPosX);
}

TEST(UnitCube, MissesAndBadDirections) {
  EXPECT_FALSE(clip_to_unit_cube({2.0f, 2.0f, 2.0f}, {1.0f, 0.0f, 0.0f}).hit);
  EXPECT_FALSE(clip_to_unit_cube({-1.0f, 0.5f, 0.5f}, {0.0f, 0.0f, 0.0f}).hit);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(clip_to_unit_cube({-1.0f, 0.5f, 0.5f}, {nan, 0.0f, 1.0f}).hit);
  EXPECT_FALSE(clip_to_unit_cube({-1.0f, 0.5f, 0.5f}, {0.0f, 1.0f, 1.0f}).hit);
}

}  // namespace
}  // namespace gfield
