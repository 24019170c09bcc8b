// d_n (gfield thickness) against the analytic answer: from a point at radius 0.999 r inside a
// sphere of radius r, along the inward radial direction, the far side is 1.999 r away (less the
// facets' sag, under 1e-4 r here); the file round-trips.

#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "gfield/thickness.hpp"
#include "preprocess/thickness.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

constexpr float kPi = 3.14159265358979f;

/// A UV sphere of radius r: `rings` x `segments` quads split into triangles.
TriangleMesh uv_sphere(double r, int rings, int segments) {
  TriangleMesh mesh;
  for (int i = 0; i <= rings; ++i) {
    const double theta = kPi * double(i) / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * kPi * double(j) / segments;
      mesh.positions.push_back(r * glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                              std::sin(theta) * std::sin(phi)));
    }
  }
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      const int a = i * segments + j, b = i * segments + (j + 1) % segments;
      const int c = a + segments, d = b + segments;
      mesh.triangles.push_back({a, c, b});
      mesh.triangles.push_back({b, c, d});
    }
  }
  return mesh;
}

TEST(Thickness, SphereFarSideIsTheDiameter) {
  const float r = 0.8f;
  // A geometry image whose covered texels sit just inside the sphere (latitude/longitude grid),
  // with the first column as padding.
  GeometryImage image;
  const int n = 32;
  image.size = n;
  image.box = {glm::vec3(-1.0f), glm::vec3(1.0f)};
  image.source = "sphere";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float theta = kPi * (float(j) + 0.5f) / float(n);
      const float phi = 2.0f * kPi * (float(i) + 0.5f) / float(n);
      const glm::vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
      image.position.push_back(0.999f * r * d);
      image.normal.push_back(d);
      image.coverage.push_back(i == 0 ? 0.0f : 1.0f);
    }
  }
  ThicknessMap map;
  ThicknessStats stats;
  std::string error;
  ASSERT_TRUE(compute_thickness(image, uv_sphere(r, 96, 192), map, stats, error)) << error;
  EXPECT_EQ(stats.covered_texels, size_t(n * (n - 1)));
  EXPECT_EQ(stats.misses, 0u);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float d = map.distance[texel_index(image, i, j)];
      if (i == 0)
        EXPECT_EQ(d, 0.0f);
      else
        EXPECT_NEAR(d, 1.999f * r, 2e-4f) << i << ", " << j;
    }
  }

  const std::string path =
      (std::filesystem::path(gfield::build_paths::test_tmp()) / "thickness_test.thickness.exr")
          .string();
  ASSERT_TRUE(save_thickness_map(path, map, error)) << error;
  ThicknessMap loaded;
  ASSERT_TRUE(load_thickness_map(path, loaded, error)) << error;
  EXPECT_EQ(loaded.size, n);
  EXPECT_EQ(loaded.source, "sphere");
  EXPECT_EQ(loaded.distance, map.distance);
  EXPECT_EQ(loaded.box.max, image.box.max);
  EXPECT_EQ(thickness_path("a/b.gimage.exr"), "a/b.thickness.exr");
}

TEST(Thickness, RejectsOtherFiles) {
  ThicknessMap map;
  std::string error;
  EXPECT_FALSE(load_thickness_map("/nonexistent/x.thickness.exr", map, error));
  EXPECT_NE(error.find("x.thickness.exr"), std::string::npos) << error;
}

}  // namespace
}  // namespace gfield
