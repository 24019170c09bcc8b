#pragma once
// A geometry field: for every line through two box samples on different faces, the
// geometry-image uvs of its hits in order along it, stored compactly (format version 3,
// shaders/lib/contract.glsl "The compact geometry field"; docs/formats.md): the hit nearest each
// end of every line in a dense table, the hits between them, for the few lines with more than
// two, in a line table by tiles. The paper's field (version 1) is the dense table alone.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"
#include "gfield/check.hpp"
#include "gfield/uninitialized_allocator.hpp"

namespace gfield {

/// uv of a miss (a line with fewer hits than asked for).
inline constexpr float kFieldMiss = -1.0f;
/// uv of a pair of samples on one face (no ray through the box).
inline constexpr float kFieldNoRay = -2.0f;
/// Hits stored per line at most (a line with more keeps the 4 nearest each end).
inline constexpr int kMaxLineHits = 8;
/// Layers K of a version-2 field (the layered layout: one table per hit).
inline constexpr int kMaxFieldLayers = 4;

struct GeometryField {
  int samples_per_side = 0;  ///< N, samples per side of each cube face
  /// K, the hits a lookup reads per line at most: the most any line holds (version 3, at most
  /// kMaxLineHits), the file's layers (version 2), 1 (version 1).
  int layers = 1;
  Box box;               ///< the box that maps to the unit cube (mesh coordinates)
  std::string source;    ///< mesh file name the field was built from
  std::string build_id;  ///< the build's id, the image's (gfield/build_id.hpp); empty: none
  /// The hit nearest the entry of every pair (entry sample, exit sample on another face):
  /// (6N^2) x (5N^2) uvs, index entry * 5N^2 + field_column(N, entry, exit); kFieldMiss.
  /// resize() leaves new entries unset (UninitializedAllocator).
  std::vector<glm::vec2, UninitializedAllocator<glm::vec2>> nearest;
  /// The line table (contract.glsl): the lines of 1 hit or of 3 and more, by tiles.
  std::vector<uint32_t> lines;
  /// The interior hits of the lines of 3 and more, from each line's lower sample.
  std::vector<glm::vec2> interior;
};

/// Samples of the box: 6 N^2 (rows of the nearest-hit table).
inline int field_side(const GeometryField& field) {
  return sample_count(field.samples_per_side);
}
/// Columns of the nearest-hit table: 5 N^2.
inline int field_columns(const GeometryField& field) {
  return 5 * field.samples_per_side * field.samples_per_side;
}
/// Entries of the nearest-hit table: 6 N^2 * 5 N^2.
inline size_t field_nearest_size(const GeometryField& field) {
  return size_t(field_side(field)) * size_t(field_columns(field));
}
/// Index in GeometryField::nearest of entry sample `entry` (in [0, 6N^2)) at `column` (in [0,
/// 5N^2): field_column of the exit sample).
inline size_t field_nearest_index(const GeometryField& field, int entry, int column) {
  GF_DCHECK(entry >= 0 && entry < field_side(field) && column >= 0 && column < field_columns(field),
            "entry or column outside the nearest-hit table");
  return size_t(entry) * size_t(field_columns(field)) + size_t(column);
}
/// Stored uv of hit `layer` (0: the nearest to the entry) along the line from the entry sample
/// towards the exit sample: a uv, kFieldMiss past its last hit, kFieldNoRay for two samples on
/// one face (gfield/field_lines.hpp reads the line table).
glm::vec2 field_uv(const GeometryField& field, int entry, int exit, int layer = 0);
/// True when a stored uv is a hit (both components >= 0).
inline bool is_field_hit(glm::vec2 uv) {
  return uv.x >= 0.0f && uv.y >= 0.0f;
}

}  // namespace gfield
