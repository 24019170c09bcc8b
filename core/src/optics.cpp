#include "gfield/optics.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

#include "gfield/glsl_names.hpp"

namespace gfield {
namespace optics_glsl {
// shaders/lib/optics.glsl in double.
using namespace gfield::glsl;
using real = double;
using rvec3 = dvec3;
#include "gfield/glsl_begin.hpp"

#include "../../shaders/lib/optics.glsl"

#include "gfield/glsl_end.hpp"
}  // namespace optics_glsl

glm::dvec3 reflect(glm::dvec3 incident, glm::dvec3 normal) {
  return optics_glsl::gf_reflect(incident, normal);
}

std::optional<glm::dvec3> refract(glm::dvec3 incident, glm::dvec3 normal, double eta) {
  const glm::dvec3 transmitted = optics_glsl::gf_refract(incident, normal, eta);
  if (transmitted == glm::dvec3(0.0))  // total internal reflection, as the shaders tell it
    return std::nullopt;
  return transmitted;
}

std::optional<double> critical_angle(double n1, double n2) {
  if (!(n1 > n2)) {
    return std::nullopt;
  }
  return std::asin(n2 / n1);
}

bool total_internal_reflection(double cos_i, double n1, double n2) {
  return optics_glsl::gf_total_internal_reflection(cos_i, n1, n2);
}

double fresnel_dielectric(double cos_i, double n1, double n2) {
  return optics_glsl::fresnel_dielectric(cos_i, n1, n2);
}

double fresnel_schlick(double cos_i, double n1, double n2) {
  cos_i = std::clamp(cos_i, 0.0, 1.0);
  if (total_internal_reflection(cos_i, n1, n2))
    return 1.0;
  double r0 = (n1 - n2) / (n1 + n2);
  r0 *= r0;
  // From the denser side the transmitted cosine stands for the incident one.
  const double eta = n1 / n2;
  const double c = n1 > n2 ? std::sqrt(1.0 - eta * eta * (1.0 - cos_i * cos_i)) : cos_i;
  const double m = 1.0 - c;
  return r0 + (1.0 - r0) * m * m * m * m * m;
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
