// The refined lookup of rays leaving a surface as the runtime casts them (gf_trace_leaving): rays
// inside a glass object and shadow rays, on spot's field at N = 24 and 8 bits, as the GPU holds
// it, against exact Embree casts. spot is closed, so a ray into its solid always meets the
// surface again and a miss is always wrong.

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

class LeavingLookup : public ::testing::Test {
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

SpotAsset* LeavingLookup::asset_ = nullptr;

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

TEST_F(LeavingLookup, RaysIntoTheSolidAlwaysMeetItsSurface) {
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

/// Shadow rays of `rays` whose exact cast hits, and how many of them the refined lookup finds,
/// as shadow rays (any_hit) or on their side alone; the lookups' work per ray as shadow rays.
struct ShadowCasts {
  size_t exact_hits = 0;
  size_t found = 0;
  size_t found_on_their_side = 0;
  double fetches_per_ray = 0.0;
  double newton_per_ray = 0.0;
};

ShadowCasts cast_shadow_rays(const SpotAsset& a, const SurfaceRays& rays) {
  ShadowCasts out;
  LookupWork work;
  FieldLookup counted = a.lookup;
  counted.work = &work;
  for (size_t i = 0; i < rays.rays.size(); ++i) {
    const Ray& r = rays.rays[i];
    const bool exact =
        intersect(a.embree, r.origin, r.direction, r.t_min, r.t_max, rays.triangles[i]).hit;
    const bool any = lookup_first_hit_leaving(counted, r, rays.self_origins[i], rays.self_t_min,
                                              rays.facing[i], LookupMode::kRefined, true)
                         .hit;
    const bool side = lookup_first_hit_leaving(a.lookup, r, rays.self_origins[i], rays.self_t_min,
                                               rays.facing[i], LookupMode::kRefined)
                          .hit;
    out.exact_hits += exact ? 1 : 0;
    out.found += exact && any ? 1 : 0;
    out.found_on_their_side += exact && side ? 1 : 0;
  }
  const double n = double(rays.rays.size());
  out.fetches_per_ray =
      double(work.counts[gpu::WORK_FIELD_FETCHES] + work.counts[gpu::WORK_IMAGE_FETCHES]) / n;
  out.newton_per_ray = double(work.counts[gpu::WORK_NEWTON_STEPS]) / n;
  return out;
}

TEST_F(LeavingLookup, ShadowRaysSearchTheirSideAndDoubtNearTheSurface) {
  // Self-shadow rays from spot's surface towards random lights. Looked up on either side, each
  // searched every candidate near the surface, the crossings of the surface it leaves: about 210
  // texel fetches and 30 Newton steps per ray. On their side alone they lose self-shadows where
  // the ray passes near the surface; a miss the lookup doubts is looked up on either side.
  const SurfaceOffsets offsets = surface_offsets(asset_->image, asset_->field.box);
  const SurfaceRays rays =
      shadow_surface_rays(asset_->embree, asset_->pm.mesh, asset_->field.box, 4000, offsets, 7);
  ASSERT_TRUE(rays.any_hit);
  const ShadowCasts c = cast_shadow_rays(*asset_, rays);
  std::printf(
      "%zu shadow rays: %zu exact hits, %zu found (%zu on their side alone); %.1f texel "
      "fetches, %.2f Newton steps per ray\n",
      rays.rays.size(), c.exact_hits, c.found, c.found_on_their_side, c.fetches_per_ray,
      c.newton_per_ray);
  EXPECT_GT(rays.rays.size(), 3900u);
  EXPECT_GT(c.exact_hits, 300u);
  EXPECT_GT(c.found, c.found_on_their_side);
  EXPECT_LE(c.fetches_per_ray, 80.0);
  EXPECT_LE(c.newton_per_ray, 8.0);
  const AccuracyStats s =
      verify_lookup(asset_->lookup, asset_->embree, asset_->pm.mesh, rays, LookupMode::kRefined);
  std::printf("shadow rays: hit/miss %.4f\n", s.hit_agreement());
  EXPECT_GE(s.hit_agreement(), 0.997);
}

}  // namespace
}  // namespace gfield
