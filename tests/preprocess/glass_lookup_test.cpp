// The refined lookup of rays inside a glass object, as the runtime casts them (gf_trace_leaving):
// spot's field at N = 24 and 8 bits, as the GPU holds it, against exact Embree casts. spot is
// closed, so a ray into its solid always meets the surface again and a miss is always wrong.

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "gfield/field_lookup.hpp"
#include "gfield/gpu_storage.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "preprocess/verify.hpp"
#include "preprocess/verify_rays.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {
namespace {

/// spot's asset built in memory as `gfield build` builds it, its field quantised to 8 bits.
struct SpotAsset {
  ParameterizedMesh pm;
  GeometryImage image;
  EmbreeMesh embree;
  GeometryField field;
  FieldLookup lookup;
};

class GlassLookup : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    asset_ = new SpotAsset();
    const std::string path = std::string(build_paths::mesh_dir()) + "/spot.obj";
    TriangleMesh mesh;
    std::string error;
    ASSERT_TRUE(load_mesh(path, mesh, error)) << error;
    GeometryImageOptions options;
    options.measure = false;
    GeometryImageReport report;
    ASSERT_TRUE(build_geometry_image(mesh, options, asset_->image, asset_->pm, report, error))
        << error;
    ASSERT_TRUE(asset_->embree.build(asset_->pm.mesh, error)) << error;
    GeometryField field;
    ASSERT_TRUE(build_geometry_field(asset_->pm, asset_->embree, asset_->image, 24, field, error))
        << error;
    asset_->field = quantized_field(field, 8);
    ASSERT_TRUE(make_field_lookup(asset_->field, asset_->image, asset_->lookup, error)) << error;
  }
  static void TearDownTestSuite() {
    delete asset_;
    asset_ = nullptr;
  }
  static SpotAsset* asset_;
};

SpotAsset* GlassLookup::asset_ = nullptr;

/// Rays of `rays` that start into the solid (facing -1) and whose exact cast hits: how many,
/// and how many of them the refined lookup answers with a miss.
struct IntoTheSolid {
  size_t rays = 0;
  size_t missed = 0;
};

IntoTheSolid rays_into_the_solid(const SpotAsset& a, const SurfaceRays& rays) {
  IntoTheSolid out;
  for (size_t i = 0; i < rays.rays.size(); ++i) {
    const Ray& r = rays.rays[i];
    if (rays.facing[i] >= 0.0f ||
        !intersect(a.embree, r.origin, r.direction, r.t_min, r.t_max, rays.triangles[i]).hit) {
      continue;
    }
    const FieldHit h = lookup_first_hit_leaving(a.lookup, r, rays.self_origins[i], rays.self_t_min,
                                                rays.facing[i], LookupMode::kRefined);
    out.rays++;
    out.missed += h.hit ? 0 : 1;
  }
  return out;
}

TEST_F(GlassLookup, RaysIntoTheSolidAlwaysMeetItsSurface) {
  // The refractions into the solid of view rays, and their next step inside it (out into the
  // open, or totally reflected back into the solid).
  const SurfaceOffsets offsets = surface_offsets(asset_->image, asset_->field.box);
  const SurfaceRays into =
      glass_surface_rays(asset_->embree, asset_->pm.mesh, asset_->field.box, 2000, offsets, 5);
  const SurfaceRays inside =
      glass_inside_rays(asset_->embree, asset_->pm.mesh, asset_->field.box, 2000, offsets, 6);
  const IntoTheSolid a = rays_into_the_solid(*asset_, into);
  const IntoTheSolid b = rays_into_the_solid(*asset_, inside);
  std::printf("into the solid: %zu of %zu missed; reflected inside it: %zu of %zu missed\n",
              a.missed, a.rays, b.missed, b.rays);
  EXPECT_GT(a.rays, 1900u);
  EXPECT_GT(b.rays, 50u);
  EXPECT_EQ(a.missed, 0u);
  EXPECT_EQ(b.missed, 0u);
  // Hits and positions against the exact casts, the refraction into the solid.
  const AccuracyStats s =
      verify_lookup(asset_->lookup, asset_->embree, asset_->pm.mesh, into, LookupMode::kRefined);
  std::printf("into the solid: hit/miss %.4f, position median %.5f%% p99 %.4f%%\n",
              s.hit_agreement(), s.position_median, s.position_p99);
  EXPECT_GE(s.hit_agreement(), 0.999);
  EXPECT_LE(s.position_median, 0.001);
  EXPECT_LE(s.position_p99, 2.0);
}

}  // namespace
}  // namespace gfield
