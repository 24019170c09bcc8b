#include "gfield/optics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gfield {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

TEST(Optics, ReflectMirrorsAboutTheNormal) {
  const glm::dvec3 r = reflect(glm::normalize(glm::dvec3(1, -1, 0)), {0, 1, 0});
  EXPECT_NEAR(r.x, std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(r.y, std::sqrt(0.5), 1e-6);
  EXPECT_NEAR(r.z, 0.0, 1e-6);
}

TEST(Optics, RefractObeysSnellsLaw) {
  // Air to glass at 30 degrees: sin(theta_t) = sin(30) / 1.5 = 1/3.
  const double theta = 30.0 * kDegree;
  const glm::dvec3 incident{std::sin(theta), -std::cos(theta), 0.0};
  const auto t = refract(incident, {0, 1, 0}, 1.0 / 1.5);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(glm::length(*t), 1.0, 1e-6);
  EXPECT_NEAR(t->x, 1.0 / 3.0, 1e-6);
  EXPECT_LT(t->y, 0.0);
  EXPECT_NEAR(t->z, 0.0, 1e-7);
  // Normal incidence passes straight through.
  const auto straight = refract({0, -1, 0}, {0, 1, 0}, 1.0 / 1.33);
  ASSERT_TRUE(straight.has_value());
  EXPECT_NEAR(straight->y, -1.0, 1e-6);
}

TEST(Optics, CriticalAngleOfGlassIs41_81Degrees) {
  const auto angle = critical_angle(1.5, 1.0);
  ASSERT_TRUE(angle.has_value());
  EXPECT_NEAR(*angle / kDegree, 41.81, 0.01);
  EXPECT_FALSE(critical_angle(1.0, 1.5).has_value());
  EXPECT_FALSE(critical_angle(1.5, 1.5).has_value());
  // Water to air: asin(1 / 1.33333) = 48.59 degrees.
  EXPECT_NEAR(*critical_angle(1.33333, 1.0) / kDegree, 48.59, 0.01);
}

TEST(Optics, TotalInternalReflectionOnlyBeyondTheCriticalAngle) {
  const double critical = *critical_angle(1.5, 1.0);
  for (double degrees = 0.0; degrees < 90.0; degrees += 0.5) {
    const double theta = degrees * kDegree;
    const bool tir = total_internal_reflection(std::cos(theta), 1.5, 1.0);
    EXPECT_EQ(tir, theta > critical) << degrees;
    const glm::dvec3 incident{std::sin(theta), -std::cos(theta), 0.0};
    EXPECT_EQ(!refract(incident, {0, 1, 0}, 1.5).has_value(), tir) << degrees;
    // Never from the less dense side.
    EXPECT_FALSE(total_internal_reflection(std::cos(theta), 1.0, 1.5));
  }
}

TEST(Optics, FresnelAtNormalIncidenceIs4PercentForGlass) {
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-6);
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.5, 1.0), 0.04, 1e-6);
  EXPECT_NEAR(fresnel_schlick(1.0, 1.0, 1.5), 0.04, 1e-6);
  // Water: ((1.33333 - 1) / 2.33333)^2 = 0.020408.
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.33333), 0.020408, 1e-5);
}

TEST(Optics, FresnelMatchesHandComputedValues) {
  // 45 degrees, air -> glass: cos_t = sqrt(1 - 0.5 / 2.25) = 0.881917;
  // rs = (0.707107 - 1.5 * 0.881917) / (0.707107 + 1.5 * 0.881917) = -0.303337,
  // rp = (1.5 * 0.707107 - 0.881917) / (1.5 * 0.707107 + 0.881917) = 0.092013;
  // R = (rs^2 + rp^2) / 2 = 0.050240.
  EXPECT_NEAR(fresnel_dielectric(std::cos(45.0 * kDegree), 1.0, 1.5), 0.050240, 5e-6);
  // Grazing incidence reflects everything.
  EXPECT_NEAR(fresnel_dielectric(0.0, 1.0, 1.5), 1.0, 1e-6);
  // Beyond the critical angle inside glass: total reflection.
  EXPECT_EQ(fresnel_dielectric(std::cos(60.0 * kDegree), 1.5, 1.0), 1.0);
  EXPECT_EQ(fresnel_schlick(std::cos(60.0 * kDegree), 1.5, 1.0), 1.0);
}

TEST(Optics, FresnelIsReciprocalAndSchlickIsClose) {
  // R is the same seen from either side of the interface along the same light path.
  for (double degrees = 0.0; degrees < 89.0; degrees += 1.0) {
    const double cos_i = std::cos(degrees * kDegree);
    const double sin_t = std::sin(degrees * kDegree) / 1.5;
    const double cos_t = std::sqrt(1.0 - sin_t * sin_t);
    EXPECT_NEAR(fresnel_dielectric(cos_i, 1.0, 1.5), fresnel_dielectric(cos_t, 1.5, 1.0), 1e-5);
    EXPECT_NEAR(fresnel_schlick(cos_i, 1.0, 1.5), fresnel_dielectric(cos_i, 1.0, 1.5), 0.06);
  }
}

TEST(Optics, PresetsFromHurleysTable) {
  EXPECT_FLOAT_EQ(*find_ior_preset("vacuum"), 1.0f);
  EXPECT_FLOAT_EQ(*find_ior_preset("air"), 1.00029f);
  EXPECT_FLOAT_EQ(*find_ior_preset("water"), 1.33333f);
  EXPECT_FLOAT_EQ(*find_ior_preset("glass"), 1.5f);
  EXPECT_FLOAT_EQ(*find_ior_preset("diamond"), 2.417f);
  EXPECT_FLOAT_EQ(*find_ior_preset("Crown Glass"), 1.53f);
  EXPECT_FLOAT_EQ(*find_ior_preset("heavy_flint_glass"), 1.65f);
  EXPECT_FLOAT_EQ(*find_ior_preset("ruby-sapphire"), 1.77f);
  EXPECT_FALSE(find_ior_preset("unobtainium").has_value());
  EXPECT_FALSE(find_ior_preset("").has_value());
  EXPECT_EQ(ior_presets().size(), 18u);
}

}  // namespace
}  // namespace gfield
