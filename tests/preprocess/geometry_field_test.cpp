// Geometry-field build with Embree and the lookups, against exact Embree casts. The asset is a
// torus grid mesh with its (periodic) grid uvs as the geometry-image parameterisation; the
// geometry image is that mesh rasterised at texel centres, so the only errors are the field's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <glm/gtc/constants.hpp>

#include "gfield/exr_io.hpp"
#include "gfield/field_lines.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/verify.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

constexpr float kPi = glm::pi<float>();
constexpr int kMajor = 72;  // grid cells around the ring
constexpr int kMinor = 36;  // grid cells around the tube

glm::vec3 torus_point(float u, float v) {
  const float a = 2.0f * kPi * u;
  const float b = 2.0f * kPi * v;
  const float r = 0.8f + 0.3f * std::cos(b);
  return {r * std::cos(a), r * std::sin(a), 0.3f * std::sin(b) + 0.1f * std::cos(3.0f * a)};
}

/// Torus grid mesh (the tube wobbles in z) with corner uvs = grid coordinates in [0,1]^2.
ParameterizedMesh make_torus() {
  ParameterizedMesh pm;
  for (int j = 0; j <= kMinor; ++j) {
    for (int i = 0; i <= kMajor; ++i) {
      pm.mesh.positions.push_back(glm::dvec3(torus_point(float(i) / kMajor, float(j) / kMinor)));
    }
  }
  const auto vertex = [](int i, int j) { return j * (kMajor + 1) + i; };
  const auto uv = [](int i, int j) { return glm::vec2(float(i) / kMajor, float(j) / kMinor); };
  for (int j = 0; j < kMinor; ++j) {
    for (int i = 0; i < kMajor; ++i) {
      pm.mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      pm.corner_uv.insert(pm.corner_uv.end(), {uv(i, j), uv(i + 1, j), uv(i + 1, j + 1)});
      pm.mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
      pm.corner_uv.insert(pm.corner_uv.end(), {uv(i, j), uv(i + 1, j + 1), uv(i, j + 1)});
    }
  }
  return pm;
}

/// The torus mesh resampled at the texel centres of an n x n image (the mesh's own piecewise
/// linear surface), with its triangles' normals.
GeometryImage rasterize_torus(const ParameterizedMesh& pm, int n, const Box& box) {
  GeometryImage image;
  image.size = n;
  image.box = box;
  image.source = "torus.obj";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const float x = (i + 0.5f) / n * kMajor;
      const float y = (j + 0.5f) / n * kMinor;
      const int ci = std::min(int(x), kMajor - 1);
      const int cj = std::min(int(y), kMinor - 1);
      const float fx = x - ci;
      const float fy = y - cj;
      // The cell's two triangles split along its (0,0)-(1,1) diagonal.
      const size_t t = 2 * size_t(cj * kMajor + ci) + (fy > fx ? 1 : 0);
      const glm::ivec3 tri = pm.mesh.triangles[t];
      const glm::vec3 p0(pm.mesh.positions[size_t(tri[0])]);
      const glm::vec3 p1(pm.mesh.positions[size_t(tri[1])]);
      const glm::vec3 p2(pm.mesh.positions[size_t(tri[2])]);
      glm::vec3 b;  // barycentrics of (fx, fy) in the triangle's uv corners
      if (fy > fx) {
        b = {1.0f - fy, fx, fy - fx};  // (0,0), (1,1), (0,1)
      } else {
        b = {1.0f - fx, fx - fy, fy};  // (0,0), (1,0), (1,1)
      }
      image.position.push_back(b.x * p0 + b.y * p1 + b.z * p2);
      image.normal.push_back(glm::normalize(glm::cross(p1 - p0, p2 - p0)));
      image.coverage.push_back(1.0f);
    }
  }
  return image;
}

struct TorusAsset {
  ParameterizedMesh pm;
  EmbreeMesh embree;
  GeometryImage image;
  GeometryField field;
  FieldBuildStats stats;
};

class GeometryFieldTorus : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    asset_ = new TorusAsset;
    asset_->pm = make_torus();
    std::string error;
    ASSERT_TRUE(asset_->embree.build(asset_->pm.mesh, error)) << error;
    std::vector<glm::vec3> points;
    for (const glm::dvec3& p : asset_->pm.mesh.positions) {
      points.push_back(glm::vec3(p));
    }
    const Box box = padded_bounds(points.data(), points.size(), 0.02f);
    asset_->image = rasterize_torus(asset_->pm, 256, box);
    ASSERT_TRUE(build_geometry_field(asset_->pm, asset_->embree, asset_->image, 10, asset_->field,
                                     error, &asset_->stats))
        << error;
    asset_->field.source = asset_->image.source;
    ready_ = true;
  }
  /// A failed suite set-up fails every test instead of letting it use what is missing.
  void SetUp() override { ASSERT_TRUE(ready_) << "the test suite's set-up failed (see above)"; }
  static void TearDownTestSuite() { delete asset_; }
  static inline bool ready_ = false;
  static TorusAsset* asset_;
};
TorusAsset* GeometryFieldTorus::asset_ = nullptr;

TEST_F(GeometryFieldTorus, TableLayoutAndBareCastAgree) {
  const GeometryField& field = asset_->field;
  const int n = field.samples_per_side;
  const int side = field_side(field);
  ASSERT_EQ(field.nearest.size(), size_t(side) * size_t(side - n * n));
  size_t hits = 0;
  for (int entry = 0; entry < side; ++entry) {
    for (int exit = 0; exit < side; ++exit) {
      const glm::vec2 uv = field_uv(field, entry, exit);
      const bool same_face = entry / (n * n) == exit / (n * n);
      EXPECT_EQ(uv == glm::vec2(kFieldNoRay), same_face);
      if (is_field_hit(uv)) {
        ++hits;
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_LE(uv.y, 1.0f);
      } else if (!same_face) {
        ASSERT_EQ(uv, glm::vec2(kFieldMiss));
      }
    }
  }
  EXPECT_EQ(hits, asset_->stats.hits);
  EXPECT_EQ(asset_->stats.rays, size_t(side) * size_t(side) - 6 * size_t(n * n) * size_t(n * n));
  // The field's rays take their hits from one traversal per line, the bare cast casts every ray:
  // they differ only where a grazing ray slips between triangles in one direction.
  const size_t bare_hits = cast_field_rays(asset_->embree, field.box, n);
  EXPECT_LE(std::max(bare_hits, hits) - std::min(bare_hits, hits), hits / 10000);
  EXPECT_EQ(cast_field_rays(asset_->embree, field.box, n, true), hits);
  // A torus seen through the box: a good share of rays hit, some miss through the hole.
  EXPECT_GT(hits, asset_->stats.rays / 4);
  EXPECT_LT(hits, asset_->stats.rays);
}

TEST_F(GeometryFieldTorus, LayersHoldTheLinesHitsInOrder) {
  // The torus: lines through the box cross it 0, 2 or 4 times (tangent lines aside): the field
  // holds every hit of every line.
  const GeometryField& field = asset_->field;
  const FieldBuildStats& stats = asset_->stats;
  EXPECT_GE(field.layers, 4);
  EXPECT_EQ(stats.lines_by_hits[kMaxLineHits + 1], 0u);
  size_t lines = 0;
  for (size_t count : stats.lines_by_hits) {
    lines += count;
  }
  EXPECT_EQ(lines, stats.rays);
  EXPECT_GT(stats.lines_by_hits[4], stats.rays / 50);  // lines through both sides of the ring
  EXPECT_GE(layer_coverage(stats, 4), 0.999);
  EXPECT_LT(layer_coverage(stats, 2), layer_coverage(stats, 4));
  // Every layer against the exact hits along the line, cast one after the other.
  const int n = field.samples_per_side;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> sample(0, sample_count(n) - 1);
  size_t compared = 0, agree = 0, close = 0, hits = 0;
  for (int i = 0; i < 3000; ++i) {
    const int entry = sample(rng), exit = sample(rng);
    if (entry / (n * n) == exit / (n * n)) {
      continue;
    }
    const glm::vec3 a = from_unit_cube(field.box, sample_point(face_sample(entry, n), n));
    const glm::vec3 d = from_unit_cube(field.box, sample_point(face_sample(exit, n), n)) - a;
    float t = 0.0f;
    for (int layer = 0; layer < field.layers; ++layer) {
      const RayHit h = intersect(asset_->embree, a, d, layer == 0 ? 0.0f : t + 1e-5f, 1.0f);
      const glm::vec2 uv = field_uv(field, entry, exit, layer);
      ++compared;
      agree += size_t(h.hit == is_field_hit(uv));
      if (h.hit && is_field_hit(uv)) {
        ++hits;
        const float error = glm::distance(sample_position(asset_->image, uv), a + h.t * d);
        close += size_t(error < 0.005f * diagonal(field.box));
      }
      t = h.hit ? h.t : 2.0f;
    }
  }
  std::printf("layers: %zu of %zu (pair, layer) hit/miss agree, %zu of %zu hits within 0.5%%\n",
              agree, compared, close, hits);
  EXPECT_GE(double(agree) / double(compared), 0.999);
  EXPECT_GE(double(close) / double(hits), 0.99);
  EXPECT_GT(hits, compared / 4);
}

TEST_F(GeometryFieldTorus, EveryLineHoldsItsHitsMirroredFromItsOtherEnd) {
  // One list per line: from the other sample, its hits in reverse order, bit for bit.
  const GeometryField& field = asset_->field;
  const int n = field.samples_per_side;
  const int side = field_side(field);
  for (int a = 0; a < side; ++a) {
    for (int b = a + 1; b < side; ++b) {
      if (a / (n * n) == b / (n * n)) {
        continue;
      }
      const LineHits forward = line_hits(field, a, b), backward = line_hits(field, b, a);
      ASSERT_EQ(forward.count, backward.count) << a << " " << b;
      for (int k = 0; k < forward.count; ++k) {
        ASSERT_EQ(forward.uv[size_t(k)], backward.uv[size_t(forward.count - 1 - k)]);
      }
    }
  }
}

TEST_F(GeometryFieldTorus, LayeredFilesHoldTheFirstHitsOfEveryLine) {
  // `gfield field --format 2`: layer l of every pair is hit l of its line, bit for bit (floats),
  // and read back the lines of at most K hits are whole again.
  const std::filesystem::path dir =
      std::filesystem::path(gfield::build_paths::test_tmp()) / "geometry_field";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "layered.gfield.exr").string();
  const GeometryField& field = asset_->field;
  std::string error;
  for (int layers : {1, kMaxFieldLayers}) {
    ASSERT_TRUE(save_layered_geometry_field(path, field, layers, ExrPrecision::kFloat, error))
        << error;
    GeometryField back;
    ASSERT_TRUE(load_geometry_field(path, back, error)) << error;
    EXPECT_EQ(back.layers, layers);
    const int side = field_side(field);
    for (int a = 0; a < side; ++a) {
      for (int b = 0; b < side; ++b) {
        for (int l = 0; l < layers; ++l) {
          ASSERT_EQ(field_uv(back, a, b, l), field_uv(field, a, b, l)) << a << " " << b << " " << l;
        }
        if (layers == kMaxFieldLayers && field_uv(field, a, b).x != kFieldNoRay &&
            line_hits(field, a, b).count <= layers) {
          ASSERT_EQ(line_hits(back, a, b).count, line_hits(field, a, b).count);
        }
      }
    }
  }
}

TEST_F(GeometryFieldTorus, SurfaceRaysSeeTheTorusBeyondTheirOrigin) {
  // Rays leaving the torus: the single-layer field holds the hits of lines from the box faces,
  // which lie behind a ray starting on the far side of the tube; the layers hold them.
  FieldLookup lookup;
  std::string error;
  ASSERT_TRUE(make_field_lookup(asset_->field, asset_->image, lookup, error)) << error;
  const SurfaceRays rays = random_surface_rays(
      asset_->pm.mesh, 5000, surface_offsets(asset_->image, asset_->field.box), 5);
  AccuracyStats k[2];
  for (int i = 0; i < 2; ++i) {
    lookup.layers = i == 0 ? 1 : 0;
    k[i] = verify_lookup(lookup, asset_->embree, asset_->pm.mesh, rays, LookupMode::kRefined);
    std::printf("surface rays K = %d: hit/miss %.4f median %.4f%%\n", i == 0 ? 1 : 4,
                k[i].hit_agreement(), k[i].position_median);
  }
  EXPECT_GE(k[1].hit_agreement(), 0.995);
  EXPECT_LE(k[1].position_median, 0.01);
  EXPECT_GT(k[1].hit_agreement(), k[0].hit_agreement() + 0.03);
}

TEST_F(GeometryFieldTorus, TableMatchesExactCasts) {
  const AccuracyStats s =
      verify_table(asset_->field, asset_->image, asset_->embree, asset_->pm.mesh, 20000, 1);
  std::printf("table: hit/miss %.5f p99 %.4f%%\n", s.hit_agreement(), s.position_p99);
  EXPECT_GE(s.hit_agreement(), 0.999);
  EXPECT_LE(s.position_p99, 0.5);
  EXPECT_GT(s.both_hit, 5000u);
}

TEST_F(GeometryFieldTorus, LookupModesAgainstExactCasts) {
  FieldLookup lookup;
  std::string error;
  ASSERT_TRUE(make_field_lookup(asset_->field, asset_->image, lookup, error)) << error;
  const std::vector<Ray> rays = random_box_rays(asset_->field.box, 10000, 1);
  AccuracyStats s[3];
  for (int m = 0; m < 3; ++m) {
    s[m] = verify_lookup(lookup, asset_->embree, asset_->pm.mesh, rays, LookupMode(m));
    std::printf("%-8s hit/miss %.4f median %.4f%% p95 %.4f%% p99 %.4f%%\n",
                lookup_mode_name(LookupMode(m)), s[m].hit_agreement(), s[m].position_median,
                s[m].position_p95, s[m].position_p99);
  }
  const AccuracyStats& refined = s[2];
  // N = 10 is coarse: the targets of N = 24 hold for `refined` even here.
  EXPECT_GE(refined.hit_agreement(), 0.99);
  EXPECT_LE(refined.position_median, 0.1);
  EXPECT_LE(refined.position_p95, 1.0);
  EXPECT_GT(refined.hit_agreement(), s[0].hit_agreement());
  EXPECT_LT(refined.position_median, s[0].position_median);
  EXPECT_LT(refined.position_median, s[1].position_median);

  const AccuracyStats last =
      verify_lookup(lookup, asset_->embree, asset_->pm.mesh, rays, LookupMode::kRefined, true);
  EXPECT_GE(last.hit_agreement(), 0.99);
  EXPECT_LE(last.position_median, 0.1);

  const std::vector<Ray> views = random_view_rays(asset_->field.box, 5000, 2);
  const AccuracyStats view =
      verify_lookup(lookup, asset_->embree, asset_->pm.mesh, views, LookupMode::kRefined);
  EXPECT_GE(view.hit_agreement(), 0.99);
  EXPECT_LE(view.position_median, 0.1);
}

TEST(GeometryField, SamplesPerSideOutOfRangeIsRefused) {
  std::string error;
  EXPECT_FALSE(check_field_size(3, true, error));
  EXPECT_NE(error.find("out of range"), std::string::npos);
  EXPECT_FALSE(check_field_size(49, true, error));
  EXPECT_TRUE(check_field_size(24, true, error)) << error;
  EXPECT_EQ(field_memory_estimate(24, true), size_t(3456) * 2880 * 12);

  ParameterizedMesh pm = make_torus();
  EmbreeMesh embree;
  ASSERT_TRUE(embree.build(pm.mesh, error)) << error;
  const GeometryImage image = rasterize_torus(pm, 16, Box{glm::vec3(-1.5f), glm::vec3(1.5f)});
  GeometryField field;
  EXPECT_FALSE(build_geometry_field(pm, embree, image, 2, field, error));
  EXPECT_FALSE(build_geometry_field(pm, embree, image, 49, field, error));
  pm.corner_uv.pop_back();
  EXPECT_FALSE(build_geometry_field(pm, embree, image, 8, field, error));
  EXPECT_NE(error.find("corner uvs"), std::string::npos);
}

TEST(GeometryField, HitsNextToPaddingSnapToTheCoveredPatches) {
  // A plane z = 0 sampled on 8 x 8 texels; columns 5..7 are padding whose copies come from far
  // away (z = 1), as dilation can produce between charts.
  GeometryImage image;
  image.size = 8;
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 8; ++i) {
      const bool covered = i < 5;
      image.position.push_back(covered ? glm::vec3(i, j, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f));
      image.normal.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
      image.coverage.push_back(covered ? 1.0f : 0.0f);
    }
  }
  const std::vector<uint8_t> patches = covered_patches(image);
  const auto uv_of = [](float i, float j) { return glm::vec2(i + 0.5f, j + 0.5f) / 8.0f; };
  // Inside the covered patches nothing moves.
  EXPECT_EQ(snap_to_covered(image, patches, uv_of(2.3f, 3.6f), glm::vec3(2.3f, 3.6f, 0.0f)),
            uv_of(2.3f, 3.6f));
  // Between the last covered column (4) and the padding: the stored uv would blend in z = 1.
  const glm::vec3 hit(4.3f, 3.5f, 0.0f);
  const glm::vec2 snapped = snap_to_covered(image, patches, uv_of(4.3f, 3.5f), hit);
  EXPECT_GT(glm::distance(sample_position(image, uv_of(4.3f, 3.5f)), hit), 0.25f);
  EXPECT_LT(glm::distance(sample_position(image, snapped), hit), 0.31f);
  EXPECT_NEAR(sample_position(image, snapped).z, 0.0f, 1e-6f);
}

TEST_F(GeometryFieldTorus, FilesRoundTripAndBadFilesAreErrors) {
  const std::filesystem::path dir =
      std::filesystem::path(gfield::build_paths::test_tmp()) / "geometry_field";
  std::filesystem::create_directories(dir);
  const std::string field_path = (dir / "torus.gfield.exr").string();
  const std::string image_path = (dir / "torus.gimage.exr").string();
  std::string error;
  ASSERT_TRUE(save_geometry_field(field_path, asset_->field, ExrPrecision::kHalf, error)) << error;
  ASSERT_TRUE(save_geometry_image(image_path, asset_->image, ExrPrecision::kFloat, error)) << error;
  GeometryField field;
  ASSERT_TRUE(load_geometry_field(field_path, field, error)) << error;
  ASSERT_EQ(field.nearest.size(), asset_->field.nearest.size());
  for (size_t i = 0; i < field.nearest.size(); i += 97) {
    ASSERT_NEAR(field.nearest[i].x, asset_->field.nearest[i].x, 1e-3f);
  }
  EXPECT_EQ(field.lines, asset_->field.lines);
  // A geometry image is not a field; a truncated field is an error naming the file.
  EXPECT_FALSE(load_geometry_field(image_path, field, error));
  EXPECT_NE(error.find(image_path), std::string::npos);
  const std::string truncated = (dir / "truncated.gfield.exr").string();
  {
    std::ifstream in(field_path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(truncated, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size() / 2));
  }
  EXPECT_FALSE(load_geometry_field(truncated, field, error));
  EXPECT_NE(error.find(truncated), std::string::npos);
}

}  // namespace
}  // namespace gfield
