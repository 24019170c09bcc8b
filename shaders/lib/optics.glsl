// Dielectric interfaces as core/src/optics.cpp computes them: exact unpolarised Fresnel
// reflectance (1 under total internal reflection); GLSL's reflect/refract use the same
// conventions (incident towards the surface, normal facing the incident side, eta = n1 / n2).

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
