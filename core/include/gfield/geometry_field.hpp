#pragma once
// A geometry field: for every pair of box samples (entry, exit), the geometry-image uvs of the
// first K hits of the line from the entry sample towards the exit sample, in order along it (one
// layer per hit; K = 1 is the paper's field).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"
#include "gfield/uninitialized_allocator.hpp"

namespace gfield {

/// uv stored for a ray that misses the surface (in a layer: the line has fewer hits).
inline constexpr float kFieldMiss = -1.0f;
/// uv stored for a pair of samples on one face (no ray through the box), in every layer.
inline constexpr float kFieldNoRay = -2.0f;
/// Hits stored per line at most (layers K of a field, 1..kMaxFieldLayers).
inline constexpr int kMaxFieldLayers = 4;

/// K layers of the (6N^2) x (6N^2) table. Entry sample index = scanline (row), exit sample index
/// = column; layer l holds the (l+1)-th hit along the line from the entry sample.
struct GeometryField {
  int samples_per_side = 0;  ///< N, samples per side of each cube face
  int layers = 1;            ///< K, hits stored per line (1..kMaxFieldLayers)
  Box box;                   ///< the box that maps to the unit cube (mesh coordinates)
  std::string source;        ///< mesh file name the field was built from
  std::string build_id;      ///< the build's id, the image's (gfield/build_id.hpp); empty: none
  /// K (6N^2)^2 uvs, index (layer * 6N^2 + entry) * 6N^2 + exit; resize() leaves new entries
  /// unset (UninitializedAllocator).
  std::vector<glm::vec2, UninitializedAllocator<glm::vec2>> uv;
};

/// Side of the table: 6 N^2.
inline int field_side(const GeometryField& field) {
  return sample_count(field.samples_per_side);
}
/// Entries of one layer: (6 N^2)^2.
inline size_t field_layer_size(const GeometryField& field) {
  return size_t(field_side(field)) * size_t(field_side(field));
}
/// Stored uv of hit `layer` (0: the first) for the pair (entry sample, exit sample).
inline glm::vec2 field_uv(const GeometryField& field, int entry, int exit, int layer = 0) {
  return field.uv[size_t(layer) * field_layer_size(field) +
                  size_t(entry) * size_t(field_side(field)) + size_t(exit)];
}
/// True when a stored uv is a hit (both components >= 0).
inline bool is_field_hit(glm::vec2 uv) {
  return uv.x >= 0.0f && uv.y >= 0.0f;
}

}  // namespace gfield
