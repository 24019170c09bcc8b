#include "preprocess/dielectric_split.hpp"

#include <algorithm>
#include <optional>

#include "gfield/optics.hpp"

namespace gfield {

bool parse_dielectric_mode(std::string_view name, DielectricMode& mode) {
  if (name == "full") {
    mode = DielectricMode::kFull;
  } else if (name == "refract-only") {
    mode = DielectricMode::kRefractOnly;
  } else if (name == "tir-only") {
    mode = DielectricMode::kTirOnly;
  } else {
    return false;
  }
  return true;
}

const char* dielectric_mode_name(DielectricMode mode) {
  switch (mode) {
    case DielectricMode::kFull:
      return "full";
    case DielectricMode::kRefractOnly:
      return "refract-only";
    case DielectricMode::kTirOnly:
      return "tir-only";
  }
  return "?";
}

InterfaceSplit split_at_interface(glm::dvec3 incident, glm::dvec3 normal, double n1, double n2,
                                  DielectricMode mode) {
  InterfaceSplit s;
  const double cos_i = std::clamp(-glm::dot(incident, normal), 0.0, 1.0);
  s.reflected = glm::normalize(reflect(incident, normal));
  const std::optional<glm::dvec3> t = refract(incident, normal, n1 / n2);
  s.total_internal_reflection = !t.has_value();
  if (t)
    s.transmitted = glm::normalize(*t);
  const double r = fresnel_dielectric(cos_i, n1, n2);
  switch (mode) {
    case DielectricMode::kFull:
      s.reflected_weight = s.total_internal_reflection ? 1.0 : r;
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0 - r;
      break;
    case DielectricMode::kRefractOnly:
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0;
      break;
    case DielectricMode::kTirOnly:
      s.reflected_weight = s.total_internal_reflection ? 1.0 : 0.0;
      s.transmitted_weight = s.total_internal_reflection ? 0.0 : 1.0;
      break;
  }
  return s;
}

}  // namespace gfield
