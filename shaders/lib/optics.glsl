// Dielectric interfaces: reflection, refraction (vector Snell), total internal reflection and the
// exact unpolarised Fresnel reflectance. Incident directions point towards the surface, normals
// face the incident side, eta = n1 / n2: GLSL's reflect and refract conventions, and gf_reflect
// and gf_refract are GLSL's formulas (the GLSL 4.50 specification, 8.5).
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md) in `real`:
// included by the shaders (float) and by core/src/optics.cpp (double: gfield/optics.hpp, the
// reference tracer's optics).

#ifndef __cplusplus
#include "lib/contract.glsl"
#endif

// The mirror direction of `incident` about unit `normal`.
rvec3 gf_reflect(rvec3 incident, rvec3 normal) {
  return incident - 2.0 * dot(normal, incident) * normal;
}

// Whether light from a medium of index n1 meeting one of n2 at cos_i (the cosine of its angle of
// incidence) is totally reflected.
bool gf_total_internal_reflection(real cos_i, real n1, real n2) {
  real eta = n1 / n2;
  return eta * eta * max(0.0, 1.0 - cos_i * cos_i) >= 1.0;
}

// The refracted direction of unit `incident` through unit `normal` at index ratio eta, or the
// zero vector under total internal reflection.
rvec3 gf_refract(rvec3 incident, rvec3 normal, real eta) {
  real cos_n = dot(normal, incident);
  real k = 1.0 - eta * eta * (1.0 - cos_n * cos_n);
  if (k < 0.0) return rvec3(0.0);
  return eta * incident - (eta * cos_n + sqrt(k)) * normal;
}

// The share of light reflected at cos_i from index n1 into n2 (1 under total internal reflection).
real fresnel_dielectric(real cos_i, real n1, real n2) {
  cos_i = clamp(cos_i, 0.0, 1.0);
  real eta = n1 / n2;
  real sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return 1.0;
  real cos_t = sqrt(1.0 - sin2_t);
  real rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  real rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  return 0.5 * (rs * rs + rp * rp);
}
