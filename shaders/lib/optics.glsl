// Dielectric interfaces: exact unpolarised Fresnel reflectance (1 under total internal
// reflection). GLSL's reflect/refract and core/include/gfield/optics.hpp use the same conventions
// (incident towards the surface, normal facing the incident side, eta = n1 / n2).
//
// ONE source for the CPU and the GPU: valid GLSL 4.50 and valid C++ with GLM, included by the
// shaders and by core/src/optics.cpp (gfield::fresnel_dielectric). Float literals with an f
// suffix; all math is float.

float fresnel_dielectric(float cos_i, float n1, float n2) {
  cos_i = clamp(cos_i, 0.0f, 1.0f);
  float eta = n1 / n2;
  float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  if (sin2_t >= 1.0f) return 1.0f;
  float cos_t = sqrt(1.0f - sin2_t);
  float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  return 0.5f * (rs * rs + rp * rp);
}
