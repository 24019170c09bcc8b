#include "gfield/optics.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace gfield {
namespace glsl {
using namespace glm;  // the GLSL vocabulary of optics.glsl
#include "../../shaders/lib/optics.glsl"
}  // namespace glsl

glm::vec3 reflect(glm::vec3 incident, glm::vec3 normal) {
  return incident - 2.0f * glm::dot(normal, incident) * normal;
}

std::optional<glm::vec3> refract(glm::vec3 incident, glm::vec3 normal, float eta) {
  const float cos_i = -glm::dot(normal, incident);
  const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
  if (k < 0.0f) {
    return std::nullopt;
  }
  return eta * incident + (eta * cos_i - std::sqrt(k)) * normal;
}

std::optional<float> critical_angle(float n1, float n2) {
  if (!(n1 > n2)) {
    return std::nullopt;
  }
  return std::asin(n2 / n1);
}

bool total_internal_reflection(float cos_i, float n1, float n2) {
  const float eta = n1 / n2;
  const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
  return sin2_t >= 1.0f;
}

float fresnel_dielectric(float cos_i, float n1, float n2) {
  return glsl::fresnel_dielectric(cos_i, n1, n2);
}

float fresnel_schlick(float cos_i, float n1, float n2) {
  cos_i = std::clamp(cos_i, 0.0f, 1.0f);
  float r0 = (n1 - n2) / (n1 + n2);
  r0 *= r0;
  float c = cos_i;
  if (n1 > n2) {
    const float eta = n1 / n2;
    const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
      return 1.0f;
    }
    c = std::sqrt(1.0f - sin2_t);
  }
  const float m = 1.0f - c;
  return r0 + (1.0f - r0) * m * m * m * m * m;
}

namespace {

// Hurley, "Approximating Refraction", table of refraction indices.
constexpr std::array<IorPreset, 18> kPresets = {{
    {"vacuum", 1.00000f},
    {"air", 1.00029f},
    {"alcohols", 1.32900f},
    {"crown-glass", 1.53000f},
    {"crystal", 2.00000f},
    {"diamond", 2.41700f},
    {"emerald", 1.57000f},
    {"fused-quartz", 1.46000f},
    {"heavy-flint-glass", 1.65000f},
    {"glass", 1.50000f},
    {"ice", 1.30900f},
    {"quartz", 1.64400f},
    {"ruby-sapphire", 1.77000f},
    {"salt", 1.54400f},
    {"sugar-solution-80", 1.49000f},
    {"sugar-solution-30", 1.38000f},
    {"topaz", 1.61000f},
    {"water", 1.33333f},
}};

// Lower case letters and digits only: "Crown Glass" and "crown-glass" both become "crownglass".
std::string canonical(std::string_view name) {
  std::string out;
  for (const char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out.push_back(char(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  return out;
}

}  // namespace

std::span<const IorPreset> ior_presets() {
  return kPresets;
}

std::optional<float> find_ior_preset(std::string_view name) {
  const std::string key = canonical(name);
  if (key.empty()) {
    return std::nullopt;
  }
  for (const IorPreset& preset : kPresets) {
    if (canonical(preset.name) == key) {
      return preset.index;
    }
  }
  return std::nullopt;
}

}  // namespace gfield
