// Albedo in the geometry image: the bundled textured mesh's geometry image
// at 512^2 against its texture looked up exactly (bilinear, at the point's own texture
// coordinates) at random points of its surface: mean colour error at most 1/255.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <vector>

#include "geometry/mesh_appearance.hpp"
#include "geometry/mesh_io.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/geometry_image.hpp"
#include "gfield/image.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

namespace fs = std::filesystem;

/// The ground truth: `image` bilinearly between texel centres at (u, v), v up from the bottom
/// row, repeating (the OBJ convention), written out here independently of the library's lookup.
glm::dvec3 exact_lookup(const Image& image, glm::dvec2 uv) {
  const double x = uv.x * image.width - 0.5, y = (1.0 - uv.y) * image.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const auto texel = [&](double i, double j) {
    const int w = image.width, h = image.height;
    const int a = ((int(i) % w) + w) % w, b = ((int(j) % h) + h) % h;
    return glm::dvec3(image.pixels[size_t(b) * size_t(w) + size_t(a)]);
  };
  const double ax = x - fx, ay = y - fy;
  return (1 - ay) * ((1 - ax) * texel(fx, fy) + ax * texel(fx + 1, fy)) +
         ay * ((1 - ax) * texel(fx, fy + 1) + ax * texel(fx + 1, fy + 1));
}

/// Which corner of input face `s` each corner of parameterised face `f` is (by position);
/// false when they are not the same three points.
bool match_corners(const TriangleMesh& input, int s, const ParameterizedMesh& pm, size_t f,
                   glm::ivec3& map) {
  map = glm::ivec3(-1);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      if (input.positions[size_t(input.triangles[size_t(s)][j])] ==
          pm.mesh.positions[size_t(pm.mesh.triangles[f][k])])
        map[k] = j;
  return map.x >= 0 && map.y >= 0 && map.z >= 0;
}

TEST(AlbedoImage, SpotPaintedAt512MatchesTheExactTextureLookup) {
  const std::string file = std::string(gfield::build_paths::mesh_dir()) + "/spot-painted.obj";
  TriangleMesh input;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
  std::string error;
  ASSERT_TRUE(load_mesh(MeshSource{file, ""}, input, &appearance, warnings, error)) << error;
  EXPECT_TRUE(warnings.empty());
  ASSERT_EQ(appearance.textures.size(), 1u);
  ASSERT_EQ(appearance.corner_uv.size(), 3 * input.triangles.size());
  GeometryImageOptions options;
  options.size = 512;
  options.measure = false;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  ASSERT_TRUE(build_geometry_image(input, options, image, pm, report, error, &appearance)) << error;
  ASSERT_EQ(image.albedo.size(), image.position.size());
  ASSERT_EQ(pm.source_face.size(), pm.mesh.triangles.size());

  // Points uniform over the surface: faces by area, then uniform barycentric weights.
  std::vector<double> areas;
  for (const glm::ivec3& t : pm.mesh.triangles) {
    const glm::dvec3 a = pm.mesh.positions[size_t(t.x)], b = pm.mesh.positions[size_t(t.y)],
                     c = pm.mesh.positions[size_t(t.z)];
    areas.push_back(0.5 * glm::length(glm::cross(b - a, c - a)));
  }
  std::mt19937 rng(17);
  std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Image& texture = appearance.textures[0].image;
  std::vector<double> errors;
  for (int n = 0; n < 20000; ++n) {
    const size_t f = pick(rng);
    const int s = pm.source_face[f];
    glm::ivec3 map;
    if (s < 0 || !match_corners(input, s, pm, f, map))
      continue;  // a face that fills a hole has no texture coordinates (spot has none)
    double a = unit(rng), c = unit(rng);
    if (a + c > 1.0)
      a = 1.0 - a, c = 1.0 - c;
    const glm::dvec3 w(1.0 - a - c, a, c);
    glm::dvec2 image_uv(0.0), texture_uv(0.0);
    for (int k = 0; k < 3; ++k) {
      image_uv += w[k] * glm::dvec2(pm.corner_uv[3 * f + size_t(k)]);
      texture_uv += w[k] * glm::dvec2(appearance.corner_uv[3 * size_t(s) + size_t(map[k])]);
    }
    const glm::dvec3 factor(
        appearance.materials[size_t(appearance.face_material[size_t(s)])].factor);
    const glm::dvec3 exact = factor * exact_lookup(texture, texture_uv);
    const glm::dvec3 stored(sample_albedo(image, glm::vec2(image_uv)));
    const double e = (std::abs(stored.r - exact.r) + std::abs(stored.g - exact.g) +
                      std::abs(stored.b - exact.b)) /
                     3.0;
    errors.push_back(e);
  }
  ASSERT_GT(errors.size(), 19000u);
  const double mean = std::accumulate(errors.begin(), errors.end(), 0.0) / double(errors.size());
  std::sort(errors.begin(), errors.end());
  const double p99 = errors[errors.size() * 99 / 100];
  std::printf(
      "albedo in the 512^2 image vs exact texture lookup at %d points: mean %.5f "
      "(%.3f/255), p99 %.4f (%.1f/255)\n",
      int(errors.size()), mean, mean * 255.0, p99, p99 * 255.0);
  EXPECT_LE(mean, 1.0 / 255.0);
}

// Filtering (each texel averages the texture over its footprint): a 1024^2 checker
// of single black and white texels on a square resampled into a 64^2 image, ~16^2 texture texels
// per image texel. Its exact average over any footprint of many texels is 1/2; a point sample
// would read 0 or 1 (aliasing).
TEST(AlbedoImage, TexelsAverageTheTextureOverTheirFootprint) {
  const fs::path dir = fs::path(gfield::build_paths::test_tmp()) / "albedo_image";
  fs::create_directories(dir);
  Image checker(1024, 1024);
  for (int y = 0; y < 1024; ++y)
    for (int x = 0; x < 1024; ++x)
      checker.pixels[size_t(y) * 1024 + size_t(x)] = glm::vec3(float((x + y) % 2));
  std::string error;
  ASSERT_TRUE(save_image((dir / "checker.png").string(), checker, error)) << error;
  std::ofstream(dir / "square.mtl") << "newmtl checker\nKd 1 1 1\nmap_Kd checker.png\n";
  std::ofstream(dir / "square.obj")
      << "mtllib square.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl checker\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
  TriangleMesh input;
  MeshAppearance appearance;
  std::vector<std::string> warnings;
  ASSERT_TRUE(
      load_mesh(MeshSource{(dir / "square.obj").string(), ""}, input, &appearance, warnings, error))
      << error;
  GeometryImageOptions options;
  options.size = 64;
  options.measure = false;
  GeometryImage image;
  ParameterizedMesh pm;
  GeometryImageReport report;
  ASSERT_TRUE(build_geometry_image(input, options, image, pm, report, error, &appearance)) << error;
  ASSERT_EQ(image.albedo.size(), image.position.size());
  double worst = 0.0;
  int covered = 0;
  for (size_t t = 0; t < image.albedo.size(); ++t) {
    if (image.coverage[t] < 1.0f)
      continue;
    ++covered;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(double(image.albedo[t][c]) - 0.5));
  }
  std::printf(
      "1024^2 single-texel checker in a 64^2 image: %d covered texels, largest "
      "deviation from the mean 0.5: %.4f\n",
      covered, worst);
  EXPECT_GT(covered, 64 * 64 / 2);
  EXPECT_LT(worst, 0.05);
}

}  // namespace
}  // namespace gfield
