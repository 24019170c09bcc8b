#pragma once
// A unit sphere as a geometry image (octahedral parameterisation) and its geometry field,
// computed analytically (no Embree, no CGAL): small test assets whose ground truth is exact.

#include <cmath>

#include <glm/glm.hpp>

#include "gfield/field_lines.hpp"
#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"

namespace gfield::test {

/// Octahedral map: uv in [0,1]^2 -> unit direction.
inline glm::vec3 octahedral_direction(glm::vec2 uv) {
  glm::vec2 p = uv * 2.0f - 1.0f;
  const float z = 1.0f - std::abs(p.x) - std::abs(p.y);
  if (z < 0.0f) {
    p = glm::vec2((1.0f - std::abs(p.y)) * (p.x >= 0.0f ? 1.0f : -1.0f),
                  (1.0f - std::abs(p.x)) * (p.y >= 0.0f ? 1.0f : -1.0f));
  }
  return glm::normalize(glm::vec3(p, z));
}

/// Inverse of octahedral_direction.
inline glm::vec2 octahedral_uv(glm::vec3 d) {
  d /= std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  glm::vec2 p(d.x, d.y);
  if (d.z < 0.0f) {
    p = glm::vec2((1.0f - std::abs(d.y)) * (d.x >= 0.0f ? 1.0f : -1.0f),
                  (1.0f - std::abs(d.x)) * (d.y >= 0.0f ? 1.0f : -1.0f));
  }
  return p * 0.5f + 0.5f;
}

/// First positive intersection parameter of o + t d with the unit sphere, or -1.
inline float sphere_hit(glm::vec3 o, glm::vec3 d) {
  const float a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0f;
  const float disc = b * b - a * c;
  if (disc < 0.0f)
    return -1.0f;
  const float t0 = (-b - std::sqrt(disc)) / a;
  const float t1 = (-b + std::sqrt(disc)) / a;
  return t0 >= 0.0f ? t0 : (t1 >= 0.0f ? t1 : -1.0f);
}

/// The unit sphere's geometry image (n x n) and field (N samples per side, two layers: where each
/// line enters the sphere and where it leaves) in the box [-1.2, 1.2]^3.
inline void make_sphere_assets(int n, int samples_per_side, GeometryImage& image,
                               GeometryField& field) {
  const Box box{glm::vec3(-1.2f), glm::vec3(1.2f)};
  image = {};
  image.size = n;
  image.box = box;
  image.source = "sphere";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const glm::vec3 d = octahedral_direction(
          glm::vec2((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n)));
      image.position.push_back(d);
      image.normal.push_back(d);
      image.coverage.push_back(1.0f);
    }
  }
  field = {};
  field.samples_per_side = samples_per_side;
  field.box = box;
  field.source = "sphere";
  const int side = sample_count(samples_per_side);
  const size_t layer_size = size_t(side) * size_t(side);
  std::vector<glm::vec2> table(2 * layer_size, glm::vec2(kFieldNoRay));  // two layers
  for (int entry = 0; entry < side; ++entry) {
    const FaceSample se = face_sample(entry, samples_per_side);
    const glm::vec3 s = from_unit_cube(box, sample_point(se, samples_per_side));
    for (int exit = 0; exit < side; ++exit) {
      const FaceSample sx = face_sample(exit, samples_per_side);
      if (sx.face == se.face)
        continue;
      const glm::vec3 e = from_unit_cube(box, sample_point(sx, samples_per_side));
      const float t = sphere_hit(s, e - s);
      const bool hit = t >= 0.0f && t <= 1.0f;
      const float t_exit = hit ? sphere_hit(e, s - e) : -1.0f;  // from the far end back
      const size_t k = size_t(entry) * size_t(side) + size_t(exit);
      table[k] = hit ? octahedral_uv(s + t * (e - s)) : glm::vec2(kFieldMiss);
      table[layer_size + k] = hit ? octahedral_uv(e + t_exit * (s - e)) : glm::vec2(kFieldMiss);
    }
  }
  compact_layered_table(table, 2, field);
}

}  // namespace gfield::test
