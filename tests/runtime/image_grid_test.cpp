// A geometry image as a grid mesh: two triangles per quad of texel centres whose four texels are
// covered, each quad split along its shorter diagonal.

#include "runtime/image_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace gfield {
namespace {

/// An n x n image on the plane z = 0 with texel (i, j) at (i * dx, j, 0), every texel covered.
GeometryImage flat_image(int n, float dx) {
  GeometryImage image;
  image.size = n;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      image.position.push_back({float(i) * dx, float(j), 0.0f});
      image.normal.push_back({0.0f, 0.0f, 1.0f});
      image.coverage.push_back(1.0f);
    }
  }
  return image;
}

/// The triangles as sorted index triples.
std::set<std::vector<unsigned>> triangles(const std::vector<unsigned>& indices) {
  std::set<std::vector<unsigned>> out;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::vector<unsigned> tri(indices.begin() + long(t), indices.begin() + long(t) + 3);
    std::sort(tri.begin(), tri.end());
    out.insert(tri);
  }
  return out;
}

TEST(ImageGrid, TwoTrianglesPerCoveredQuadAlongItsShorterDiagonal) {
  // 3 x 3 texels: 4 quads, 8 triangles, each quad's diagonals equal: split from corner 0 to 4.
  const GeometryImage square = flat_image(3, 1.0f);
  const std::vector<unsigned> all = geometry_image_triangles(square);
  ASSERT_EQ(all.size(), 8u * 3u);
  EXPECT_TRUE(triangles(all).count({0, 1, 4}));
  EXPECT_TRUE(triangles(all).count({0, 3, 4}));
  // Any index is a texel; every triangle is counter-clockwise seen from +z (the image's normal).
  for (size_t t = 0; t < all.size(); t += 3) {
    const glm::vec3 a = square.position[all[t]], b = square.position[all[t + 1]],
                    c = square.position[all[t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
  }
  // A sheared grid: texel (i, j) at (i + j, j). The quad's diagonal from (i + 1, j) to
  // (i, j + 1) is the shorter one, so the split joins texels 1 and 3.
  GeometryImage sheared = square;
  for (int t = 0; t < 9; ++t)
    sheared.position[size_t(t)].x += float(t / 3);
  EXPECT_TRUE(triangles(geometry_image_triangles(sheared)).count({1, 3, 4}));
  EXPECT_FALSE(triangles(geometry_image_triangles(sheared)).count({0, 1, 4}));
}

TEST(ImageGrid, AQuadWithAnUncoveredCornerIsLeftOut) {
  GeometryImage image = flat_image(3, 1.0f);
  image.coverage[4] = 0.5f;  // the middle texel, a corner of all four quads (A > 0.5 covers)
  EXPECT_TRUE(geometry_image_triangles(image).empty());
  image.coverage[4] = 1.0f;
  image.coverage[0] = 0.0f;  // a corner of the first quad only
  EXPECT_EQ(geometry_image_triangles(image).size(), 6u * 3u);
}

}  // namespace
}  // namespace gfield
