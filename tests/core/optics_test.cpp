#include "gfield/optics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace gfield {
namespace {

constexpr float kDegree = 3.14159265358979f / 180.0f;

TEST(Optics, ReflectMirrorsAboutTheNormal) {
  const glm::vec3 r = reflect(glm::normalize(glm::vec3(1, -1, 0)), {0, 1, 0});
  EXPECT_NEAR(r.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(r.y, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(r.z, 0.0f, 1e-6f);
}

TEST(Optics, RefractObeysSnellsLaw) {
  // Air to glass at 30 degrees: sin(theta_t) = sin(30) / 1.5 = 1/3.
  const float theta = 30.0f * kDegree;
  const glm::vec3 incident{std::sin(theta), -std::cos(theta), 0.0f};
  const auto t = refract(incident, {0, 1, 0}, 1.0f / 1.5f);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(glm::length(*t), 1.0f, 1e-6f);
  EXPECT_NEAR(t->x, 1.0f / 3.0f, 1e-6f);
  EXPECT_LT(t->y, 0.0f);
  EXPECT_NEAR(t->z, 0.0f, 1e-7f);
  // Normal incidence passes straight through.
  const auto straight = refract({0, -1, 0}, {0, 1, 0}, 1.0f / 1.33f);
  ASSERT_TRUE(straight.has_value());
  EXPECT_NEAR(straight->y, -1.0f, 1e-6f);
}

TEST(Optics, CriticalAngleOfGlassIs41_81Degrees) {
  const auto angle = critical_angle(1.5f, 1.0f);
  ASSERT_TRUE(angle.has_value());
  EXPECT_NEAR(*angle / kDegree, 41.81f, 0.01f);
  EXPECT_FALSE(critical_angle(1.0f, 1.5f).has_value());
  EXPECT_FALSE(critical_angle(1.5f, 1.5f).has_value());
  // Water to air: asin(1 / 1.33333) = 48.59 degrees.
  EXPECT_NEAR(*critical_angle(1.33333f, 1.0f) / kDegree, 48.59f, 0.01f);
}

TEST(Optics, TotalInternalReflectionOnlyBeyondTheCriticalAngle) {
  const float critical = *critical_angle(1.5f, 1.0f);
  for (float degrees = 0.0f; degrees < 90.0f; degrees += 0.5f) {
    const float theta = degrees * kDegree;
    const bool tir = total_internal_reflection(std::cos(theta), 1.5f, 1.0f);
    EXPECT_EQ(tir, theta > critical) << degrees;
    const glm::vec3 incident{std::sin(theta), -std::cos(theta), 0.0f};
    EXPECT_EQ(!refract(incident, {0, 1, 0}, 1.5f).has_value(), tir) << degrees;
    // Never from the less dense side.
    EXPECT_FALSE(total_internal_reflection(std::cos(theta), 1.0f, 1.5f));
  }
}

TEST(Optics, FresnelAtNormalIncidenceIs4PercentForGlass) {
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.5f, 1.0f), 0.04f, 1e-6f);
  EXPECT_NEAR(fresnel_schlick(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);
  // Water: ((1.33333 - 1) / 2.33333)^2 = 0.020408.
  EXPECT_NEAR(fresnel_dielectric(1.0f, 1.0f, 1.33333f), 0.020408f, 1e-5f);
}

TEST(Optics, FresnelMatchesHandComputedValues) {
  // 45 degrees, air -> glass: cos_t = sqrt(1 - 0.5 / 2.25) = 0.881917;
  // rs = (0.707107 - 1.5 * 0.881917) / (0.707107 + 1.5 * 0.881917) = -0.303337,
  // rp = (1.5 * 0.707107 - 0.881917) / (1.5 * 0.707107 + 0.881917) = 0.092013;
  // R = (rs^2 + rp^2) / 2 = 0.050240.
  EXPECT_NEAR(fresnel_dielectric(std::cos(45.0f * kDegree), 1.0f, 1.5f), 0.050240f, 5e-6f);
  // Grazing incidence reflects everything.
  EXPECT_NEAR(fresnel_dielectric(0.0f, 1.0f, 1.5f), 1.0f, 1e-6f);
  // Beyond the critical angle inside glass: total reflection.
  EXPECT_EQ(fresnel_dielectric(std::cos(60.0f * kDegree), 1.5f, 1.0f), 1.0f);
  EXPECT_EQ(fresnel_schlick(std::cos(60.0f * kDegree), 1.5f, 1.0f), 1.0f);
}

TEST(Optics, FresnelIsReciprocalAndSchlickIsClose) {
  // R is the same seen from either side of the interface along the same light path.
  for (float degrees = 0.0f; degrees < 89.0f; degrees += 1.0f) {
    const float cos_i = std::cos(degrees * kDegree);
    const float sin_t = std::sin(degrees * kDegree) / 1.5f;
    const float cos_t = std::sqrt(1.0f - sin_t * sin_t);
    EXPECT_NEAR(fresnel_dielectric(cos_i, 1.0f, 1.5f), fresnel_dielectric(cos_t, 1.5f, 1.0f),
                1e-5f);
    EXPECT_NEAR(fresnel_schlick(cos_i, 1.0f, 1.5f), fresnel_dielectric(cos_i, 1.0f, 1.5f), 0.06f);
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
