// CPU geometry-field lookup against an analytic sphere: the geometry image samples a lat-long
// map of the sphere, the field stores the exact analytic uvs of each sample pair's two hits (two
// layers), and every lookup is compared with the exact ray-sphere intersection.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gfield/field_lookup.hpp"

#include "gfield/field_lines.hpp"

namespace gfield {
namespace {

constexpr float kPi = glm::pi<float>();

struct Sphere {
  glm::vec3 centre{0.1f, -0.05f, 0.0f};
  float radius = 0.7f;

  glm::vec3 point(glm::vec2 uv) const {
    const float phi = 2.0f * kPi * uv.x;
    const float theta = kPi * uv.y;
    return centre + radius * glm::vec3(std::sin(theta) * std::cos(phi),
                                       std::sin(theta) * std::sin(phi), std::cos(theta));
  }
  glm::vec2 uv(glm::vec3 p) const {
    const glm::vec3 q = (p - centre) / radius;
    float phi = std::atan2(q.y, q.x);
    if (phi < 0.0f) {
      phi += 2.0f * kPi;
    }
    return {phi / (2.0f * kPi), std::acos(glm::clamp(q.z, -1.0f, 1.0f)) / kPi};
  }
  /// First (or last) t of o + t d in [t_min, t_max]; negative infinity-free: false when none.
  bool intersect(glm::vec3 o, glm::vec3 d, float t_min, float t_max, bool last, float& t) const {
    const glm::vec3 oc = o - centre;
    const float a = glm::dot(d, d);
    const float b = glm::dot(oc, d);
    const float c = glm::dot(oc, oc) - radius * radius;
    const float disc = b * b - a * c;
    if (disc < 0.0f) {
      return false;
    }
    const float t0 = (-b - std::sqrt(disc)) / a;
    const float t1 = (-b + std::sqrt(disc)) / a;
    const float order[2] = {last ? t1 : t0, last ? t0 : t1};
    for (float candidate : order) {
      if (candidate >= t_min && candidate <= t_max) {
        t = candidate;
        return true;
      }
    }
    return false;
  }
};

struct SphereAsset {
  Sphere sphere;
  GeometryImage image;
  GeometryField field;
  FieldLookup lookup;
};

/// Geometry image n^2 of the sphere's lat-long map and the field with N samples per side and two
/// layers (the line's entry into the sphere and its exit).
void make_sphere_asset(SphereAsset& asset, int n, int samples) {
  const Sphere& s = asset.sphere;
  const Box box{glm::vec3(-1.0f, -0.9f, -0.8f), glm::vec3(1.2f, 0.9f, 0.85f)};
  GeometryImage& image = asset.image;
  image.size = n;
  image.box = box;
  image.source = "sphere";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const glm::vec3 p = s.point({(i + 0.5f) / float(n), (j + 0.5f) / float(n)});
      image.position.push_back(p);
      image.normal.push_back(glm::normalize(p - s.centre));
      image.coverage.push_back(1.0f);
    }
  }
  GeometryField& field = asset.field;
  field.samples_per_side = samples;
  field.layers = 2;
  field.box = box;
  field.source = "sphere";
  const size_t side = size_t(sample_count(samples));
  std::vector<glm::vec2> table(2 * side * side);  // two layers, as a version-2 file holds them
  for (int entry = 0; entry < int(side); ++entry) {
    const FaceSample fe = face_sample(entry, samples);
    const glm::vec3 o = from_unit_cube(box, sample_point(fe, samples));
    for (int exit = 0; exit < int(side); ++exit) {
      const FaceSample fx = face_sample(exit, samples);
      glm::vec2 uv[2] = {glm::vec2(kFieldNoRay), glm::vec2(kFieldNoRay)};
      if (fe.face != fx.face) {
        const glm::vec3 d = from_unit_cube(box, sample_point(fx, samples)) - o;
        float t[2] = {0.0f, 0.0f};
        const bool hit =
            s.intersect(o, d, 0.0f, 1.0f, false, t[0]) && s.intersect(o, d, 0.0f, 1.0f, true, t[1]);
        for (int layer = 0; layer < 2; ++layer) {
          uv[layer] = hit ? s.uv(o + t[layer] * d) : glm::vec2(kFieldMiss);
        }
      }
      for (int layer = 0; layer < 2; ++layer) {
        table[size_t(layer) * side * side + size_t(entry) * side + size_t(exit)] = uv[layer];
      }
    }
  }
  compact_layered_table(table, 2, field);
  std::string error;
  ASSERT_TRUE(make_field_lookup(field, image, asset.lookup, error)) << error;
}

/// Segments between random points on two different faces of the box.
std::vector<Ray> box_rays(const Box& box, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const int f0 = int(rng() % 6);
    const int f1 = (f0 + 1 + int(rng() % 5)) % 6;
    const glm::vec3 a = from_unit_cube(box, face_point(f0, {unit(rng), unit(rng)}));
    const glm::vec3 b = from_unit_cube(box, face_point(f1, {unit(rng), unit(rng)}));
    rays.push_back({a, b - a, 0.0f, 1.0f});
  }
  return rays;
}

struct Accuracy {
  double agreement = 0.0;
  double median = 0.0;  // % of the diagonal
  double p95 = 0.0;
};

Accuracy measure(const SphereAsset& asset, const std::vector<Ray>& rays, LookupMode mode,
                 bool last) {
  int agree = 0;
  std::vector<double> errors;
  const float diag = diagonal(asset.field.box);
  for (const Ray& ray : rays) {
    const FieldHit h =
        last ? lookup_last_hit(asset.lookup, ray, mode) : lookup_first_hit(asset.lookup, ray, mode);
    float t = 0.0f;
    const bool exact =
        asset.sphere.intersect(ray.origin, ray.direction, ray.t_min, ray.t_max, last, t);
    agree += int(h.hit == exact);
    if (h.hit && exact) {
      errors.push_back(100.0 * glm::distance(h.position, ray.origin + t * ray.direction) / diag);
    }
  }
  Accuracy a;
  a.agreement = double(agree) / double(rays.size());
  std::sort(errors.begin(), errors.end());
  if (!errors.empty()) {
    a.median = errors[errors.size() / 2];
    a.p95 = errors[size_t(0.95 * double(errors.size() - 1))];
  }
  return a;
}

class FieldLookupSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    asset_ = new SphereAsset;
    make_sphere_asset(*asset_, 256, 12);
  }
  static void TearDownTestSuite() { delete asset_; }
  static SphereAsset* asset_;
};
SphereAsset* FieldLookupSphere::asset_ = nullptr;

TEST_F(FieldLookupSphere, RefinedMeetsTargetsAndBeatsThePaperKernels) {
  const std::vector<Ray> rays = box_rays(asset_->field.box, 10000, 7);
  const Accuracy nearest = measure(*asset_, rays, LookupMode::kNearest, false);
  const Accuracy linear = measure(*asset_, rays, LookupMode::kLinear, false);
  const Accuracy refined = measure(*asset_, rays, LookupMode::kRefined, false);
  for (const Accuracy* a : {&nearest, &linear, &refined}) {
    std::printf("hit/miss %.4f  median %.4f%%  p95 %.4f%%\n", a->agreement, a->median, a->p95);
  }
  EXPECT_GE(refined.agreement, 0.99);
  EXPECT_LE(refined.median, 0.1);
  EXPECT_LE(refined.p95, 1.0);
  EXPECT_GE(refined.agreement, nearest.agreement);
  EXPECT_LT(refined.median, nearest.median);
  EXPECT_LT(refined.median, linear.median);
  // The paper's kernels at N = 12 are far from exact: the test can tell the modes apart.
  EXPECT_GT(nearest.median, 0.3);
}

TEST_F(FieldLookupSphere, LastHitIsTheFarSide) {
  const std::vector<Ray> rays = box_rays(asset_->field.box, 4000, 11);
  const Accuracy refined = measure(*asset_, rays, LookupMode::kRefined, true);
  EXPECT_GE(refined.agreement, 0.99);
  EXPECT_LE(refined.median, 0.1);
  // From inside the sphere (a refracted ray), the last hit is where the ray leaves it.
  const Sphere& s = asset_->sphere;
  const Ray inside{s.centre, glm::vec3(0.3f, 0.5f, -0.2f), 0.0f};
  const FieldHit h = lookup_last_hit(asset_->lookup, inside, LookupMode::kRefined);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(glm::distance(h.position, s.centre), s.radius, 1e-3f);
  EXPECT_NEAR(h.distance, s.radius, 1e-3f);
  EXPECT_GT(glm::dot(h.position - s.centre, inside.direction), 0.0f);
  EXPECT_GT(glm::dot(h.normal, glm::normalize(h.position - s.centre)), 0.999f);
}

/// Rays from uniform random points of the sphere in uniform random directions (t from 1e-3 on):
/// those going inwards hit the far side, those going outwards leave.
std::vector<Ray> surface_rays(const Sphere& s, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> gauss;
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 n = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec3 d = glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    rays.push_back({s.centre + s.radius * n, d, 1e-3f});
  }
  return rays;
}

TEST_F(FieldLookupSphere, RaysLeavingTheSurfaceSeeItBeyondTheirOriginWithTwoLayers) {
  // Going inwards, the exit lies behind the line's first hit (the origin): only the second
  // layer holds it. The first hit beyond the origin is exact when it is looked up over both.
  const std::vector<Ray> rays = surface_rays(asset_->sphere, 4000, 13);
  SphereAsset one_layer = *asset_;
  one_layer.lookup.field = &one_layer.field;
  one_layer.lookup.image = &one_layer.image;
  one_layer.lookup.layers = 1;
  const Accuracy k1 = measure(one_layer, rays, LookupMode::kRefined, false);
  const Accuracy k2 = measure(*asset_, rays, LookupMode::kRefined, false);
  const Accuracy nearest = measure(*asset_, rays, LookupMode::kNearest, false);
  std::printf("surface rays, refined K = 1: %.4f, K = 2: %.4f (median %.4f%%), nearest %.4f\n",
              k1.agreement, k2.agreement, k2.median, nearest.agreement);
  // Measured 0.993: rays crossing the lat-long map's seam strip (u = 0 = 1, no patch there) and
  // poles fail to verify, as box rays do (RefinedMeetsTargetsAndBeatsThePaperKernels: 0.998).
  EXPECT_GE(k2.agreement, 0.99);
  EXPECT_LE(k2.median, 0.01);
  EXPECT_LT(k1.agreement, 0.9);  // half the rays go inwards: the single layer misses their exit
  EXPECT_GT(k2.agreement, nearest.agreement);
}

TEST_F(FieldLookupSphere, RaysInsideTheSolidFindTheExit) {
  // A refracted ray inside the sphere (origin anywhere inside, t >= 0): its first hit beyond the
  // origin is where it leaves, in every mode.
  std::mt19937 rng(17);
  std::normal_distribution<float> gauss;
  const Sphere& s = asset_->sphere;
  std::vector<Ray> rays;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 offset = 0.6f * s.radius * glm::vec3(gauss(rng), gauss(rng), gauss(rng));
    const glm::vec3 origin =
        s.centre + offset * std::min(1.0f, 0.9f * s.radius / glm::length(offset));
    rays.push_back({origin, glm::vec3(gauss(rng), gauss(rng), gauss(rng)), 0.0f});
  }
  const Accuracy refined = measure(*asset_, rays, LookupMode::kRefined, false);
  EXPECT_GE(refined.agreement, 0.993);  // measured 0.9965 (the seam strip and the poles)
  EXPECT_LE(refined.median, 0.01);
  for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear}) {
    EXPECT_GE(measure(*asset_, rays, mode, false).agreement, 0.97) << lookup_mode_name(mode);
  }
}

TEST_F(FieldLookupSphere, ViewRaysFromOutsideTheBox) {
  std::mt19937 rng(3);
  std::normal_distribution<float> gauss;
  const Sphere& s = asset_->sphere;
  int agree = 0;
  int total = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 eye =
        s.centre + 4.0f * glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec3 target = s.centre + 0.6f * glm::vec3(gauss(rng), gauss(rng), gauss(rng));
    const Ray ray{eye, glm::normalize(target - eye), 0.0f};
    const FieldHit h = lookup_first_hit(asset_->lookup, ray, LookupMode::kRefined);
    float t = 0.0f;
    const bool exact = s.intersect(ray.origin, ray.direction, 0.0f, ray.t_max, false, t);
    agree += int(h.hit == exact);
    ++total;
    if (h.hit && exact) {
      EXPECT_NEAR(h.t, t, 0.02f);
      EXPECT_NEAR(h.distance, t, 0.02f);
    }
  }
  EXPECT_GE(double(agree) / total, 0.99);
}

TEST_F(FieldLookupSphere, InstancesApplyTheTransformFirst) {
  const glm::mat4 object_to_world =
      glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, -2.0f, 1.0f)), 0.7f,
                             glm::normalize(glm::vec3(1.0f, 2.0f, 0.5f))),
                 glm::vec3(2.0f));
  const Sphere& s = asset_->sphere;
  const glm::vec3 centre = glm::vec3(object_to_world * glm::vec4(s.centre, 1.0f));
  const float radius = 2.0f * s.radius;
  std::mt19937 rng(5);
  std::normal_distribution<float> gauss;
  int hits = 0;
  for (int i = 0; i < 500; ++i) {
    const glm::vec3 eye =
        centre + 10.0f * glm::normalize(glm::vec3(gauss(rng), gauss(rng), gauss(rng)));
    const glm::vec3 target = centre + 0.5f * glm::vec3(gauss(rng), gauss(rng), gauss(rng));
    const Ray ray{eye, glm::normalize(target - eye), 0.0f};
    const FieldHit h = lookup_instance(asset_->lookup, object_to_world, ray, LookupMode::kRefined);
    if (!h.hit) {
      continue;
    }
    ++hits;
    EXPECT_NEAR(glm::distance(h.position, centre), radius, 2e-3f);
    EXPECT_NEAR(glm::distance(eye + h.t * ray.direction, h.position), 0.0f, 2e-3f);
    EXPECT_NEAR(h.distance, glm::distance(eye, h.position), 2e-3f);
    EXPECT_GT(glm::dot(h.normal, glm::normalize(h.position - centre)), 0.999f);
  }
  EXPECT_GT(hits, 200);
}

TEST_F(FieldLookupSphere, BadRaysAreMissesWithAnError) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Ray bad[] = {{glm::vec3(0.0f), glm::vec3(0.0f), 0.0f, 1.0f},
                     {glm::vec3(0.0f), glm::vec3(nan, 0.0f, 1.0f), 0.0f, 1.0f},
                     {glm::vec3(nan), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, 1.0f},
                     {glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f), 2.0f, 1.0f}};
  for (const Ray& ray : bad) {
    std::string error;
    EXPECT_FALSE(check_ray(ray, error));
    EXPECT_FALSE(error.empty());
    for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
      EXPECT_FALSE(lookup_first_hit(asset_->lookup, ray, mode).hit);
      EXPECT_FALSE(lookup_last_hit(asset_->lookup, ray, mode).hit);
    }
  }
  std::string error;
  EXPECT_TRUE(check_ray({glm::vec3(0.0f, 0.0f, -5.0f), glm::vec3(0.0f, 0.0f, 1.0f)}, error));
}

TEST_F(FieldLookupSphere, FieldAndImageMustBelongTogether) {
  FieldLookup lookup;
  std::string error;
  GeometryField moved = asset_->field;
  moved.box.max.x += 0.1f;
  EXPECT_FALSE(make_field_lookup(moved, asset_->image, lookup, error));
  EXPECT_NE(error.find("box"), std::string::npos);
  GeometryField other = asset_->field;
  other.source = "torus";
  EXPECT_FALSE(make_field_lookup(other, asset_->image, lookup, error));
  EXPECT_NE(error.find("torus"), std::string::npos);
  GeometryField truncated = asset_->field;
  truncated.nearest.pop_back();
  EXPECT_FALSE(make_field_lookup(truncated, asset_->image, lookup, error));
  GeometryField more_layers = asset_->field;
  more_layers.layers = kMaxLineHits + 1;
  EXPECT_FALSE(make_field_lookup(more_layers, asset_->image, lookup, error));
  EXPECT_NE(error.find("layers K outside [1, 8]"), std::string::npos) << error;
}

TEST(LookupMode, NamesRoundTrip) {
  for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
    LookupMode parsed = LookupMode::kNearest;
    EXPECT_TRUE(parse_lookup_mode(lookup_mode_name(mode), parsed));
    EXPECT_EQ(parsed, mode);
  }
  LookupMode parsed;
  EXPECT_FALSE(parse_lookup_mode("cubic", parsed));
}

}  // namespace
}  // namespace gfield
