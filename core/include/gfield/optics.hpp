#pragma once
// Optics of smooth dielectric interfaces: reflection, refraction (vector Snell), critical angle,
// total internal reflection, Fresnel reflectance, and named refractive indices. In double: the
// reference tracer's ground truth. Reflection, refraction, total internal reflection and the
// exact Fresnel reflectance are shaders/lib/optics.glsl, the shaders' own, compiled in double.
//
// Conventions (as GLSL's reflect/refract): `incident` points towards the surface, `normal` is a
// unit vector facing the incident side (dot(incident, normal) <= 0), eta = n_incident /
// n_transmitted.

#include <optional>
#include <span>
#include <string_view>

#include <glm/glm.hpp>

namespace gfield {

/// Mirror direction of `incident` about `normal`: I - 2 dot(N, I) N.
glm::dvec3 reflect(glm::dvec3 incident, glm::dvec3 normal);

/// Transmitted direction by Snell's law (unit when `incident` is unit), or nullopt on total
/// internal reflection.
std::optional<glm::dvec3> refract(glm::dvec3 incident, glm::dvec3 normal, double eta);

/// Critical angle in radians for light going from index n1 into n2; nullopt when n1 <= n2.
std::optional<double> critical_angle(double n1, double n2);

/// True when light at incidence cosine `cos_i` (>= 0) from n1 into n2 is totally reflected.
bool total_internal_reflection(double cos_i, double n1, double n2);

/// Exact unpolarised Fresnel reflectance of a dielectric interface (mean of s and p), for
/// incidence cosine `cos_i` in [0,1] from n1 into n2; 1 under total internal reflection.
double fresnel_dielectric(double cos_i, double n1, double n2);

/// Schlick's approximation R0 + (1 - R0)(1 - cos)^5; beyond the critical angle it returns 1 and
/// from the denser side it uses the transmitted cosine, as is standard.
double fresnel_schlick(double cos_i, double n1, double n2);

/// A named refractive index (Hurley, "Approximating Refraction", its table).
struct IorPreset {
  std::string_view name;  ///< lower case, words joined by '-', e.g. "crown-glass"
  float index;
};

/// All presets, in the article's order.
std::span<const IorPreset> ior_presets();

/// Index for a preset name; case, spaces, '-' and '_' are ignored ("Crown Glass" = "crown-glass").
std::optional<float> find_ior_preset(std::string_view name);

}  // namespace gfield
