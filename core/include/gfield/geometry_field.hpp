#pragma once
// A geometry field: for every pair of box samples (entry, exit), the geometry-image uv of the
// first hit of the ray from the entry sample towards the exit sample.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"

namespace gfield {

/// uv stored for a ray that misses the surface.
inline constexpr float kFieldMiss = -1.0f;
/// uv stored for a pair of samples on one face (no ray through the box).
inline constexpr float kFieldNoRay = -2.0f;

/// The (6N^2) x (6N^2) table. Entry sample index = scanline (row), exit sample index = column.
struct GeometryField {
  int samples_per_side = 0;   ///< N, samples per side of each cube face
  Box box;                    ///< the box that maps to the unit cube (mesh coordinates)
  std::string source;         ///< mesh file name the field was built from
  std::string build_id;       ///< the build's id, the image's (gfield/build_id.hpp); empty: none
  std::vector<glm::vec2> uv;  ///< (6N^2)^2 geometry-image uvs, index entry * 6N^2 + exit
};

/// Side of the table: 6 N^2.
inline int field_side(const GeometryField& field) {
  return sample_count(field.samples_per_side);
}
/// Stored uv for the pair (entry sample, exit sample).
inline glm::vec2 field_uv(const GeometryField& field, int entry, int exit) {
  return field.uv[size_t(entry) * size_t(field_side(field)) + size_t(exit)];
}
/// True when a stored uv is a hit (both components >= 0).
inline bool is_field_hit(glm::vec2 uv) {
  return uv.x >= 0.0f && uv.y >= 0.0f;
}

}  // namespace gfield
