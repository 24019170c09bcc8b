#pragma once
// What the reference tracer does at a dielectric surface: the mode (full Fresnel split,
// refraction only, refraction or total internal reflection) and the reflected and transmitted
// rays with their weights.

#include <string_view>

#include <glm/glm.hpp>

namespace gfield {

/// What happens at a dielectric surface.
///  kFull:        reflected and refracted rays, weighted by the exact Fresnel reflectance R and
///                1 - R (1 and 0 under total internal reflection).
///  kRefractOnly: only the refracted ray, weight 1; under total internal reflection the path ends
///                (black).
///  kTirOnly:     the refracted ray with weight 1, or, under total internal reflection only, the
///                reflected ray with weight 1 (the references of Davis & Wyman 2007, Fig. 8).
enum class DielectricMode { kFull, kRefractOnly, kTirOnly };

/// "full", "refract-only", "tir-only" -> mode; false for anything else.
bool parse_dielectric_mode(std::string_view name, DielectricMode& mode);
const char* dielectric_mode_name(DielectricMode mode);

/// Reflectance and transmittance at one dielectric interface, as the tracer uses them.
struct InterfaceSplit {
  bool total_internal_reflection = false;
  double reflected_weight = 0.0;
  double transmitted_weight = 0.0;
  glm::dvec3 reflected{0.0};
  glm::dvec3 transmitted{0.0};  ///< zero under total internal reflection
};

/// The split of unit `incident` at a surface with unit normal `normal` facing the incident side,
/// from index n1 into n2, under `mode`.
InterfaceSplit split_at_interface(glm::dvec3 incident, glm::dvec3 normal, double n1, double n2,
                                  DielectricMode mode);

}  // namespace gfield
