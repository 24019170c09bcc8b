#pragma once
// The lines of a compact geometry field (gfield/geometry_field.hpp; the layout and its addressing
// are shaders/lib/contract.glsl's, its reading shaders/lib/field_lines.glsl's, both compiled
// here too): storing a line's hits, packing the line table, reading a line back, checking a
// table read from a file, and converting a layered (version 1 or 2) table.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/geometry_field.hpp"

namespace gfield {

/// The hits of one line in order from one of its samples: `count` uvs (at most kMaxLineHits).
struct LineHits {
  int count = 0;
  std::array<glm::vec2, kMaxLineHits> uv{};
};

/// Column of `exit` in `entry`'s row of the nearest-hit table (their faces differ).
int field_column(int samples_per_side, int entry, int exit);

/// A line the nearest-hit table alone does not describe (1 hit, or 3 and more), for the line
/// table: its lower sample, its column in that sample's row, its count and its interior hits
/// (the 2nd to the second-to-last from the lower sample).
struct TableLine {
  uint32_t low = 0;
  uint32_t column = 0;
  int count = 0;
  std::array<glm::vec2, kMaxLineHits - 2> interior{};
};

/// Sizes `field.nearest` for N = field.samples_per_side (entries unset) and empties the line
/// table.
void reset_field_tables(GeometryField& field);

/// Stores the line (low, high), low < high on different faces, whose hits from `low` are `hits`:
/// its nearest hits into the nearest-hit table and, when the table alone does not tell them,
/// the line into `table_lines`. Lines may be stored from several threads at once (each its own
/// `table_lines`).
void store_line(GeometryField& field, int low, int high, const LineHits& hits,
                std::vector<TableLine>& table_lines);

/// Builds `field.lines` and `field.interior` from every stored table line (any order; sorted
/// here) and sets `field.layers` to the most hits a line holds (2 when any line hits and none
/// holds more, 1 when none hits).
void pack_line_table(std::vector<TableLine>& table_lines, GeometryField& field);

/// The hits of the line from `entry` towards `exit` (different faces), in order from `entry`.
LineHits line_hits(const GeometryField& field, int entry, int exit);

/// The first `layers` (at most kMaxLineHits) hits of the pair (entry, exit) as the layered
/// format holds them: uv[l] = field_uv(field, entry, exit, l), the line read once.
void layered_pair(const GeometryField& field, int entry, int exit, int layers, glm::vec2* uv);

/// Checks a field read from a file: the tables' sizes against N, every nearest hit a uv in
/// [0,1]^2 or a miss, every interior hit a uv, and the line table exactly as pack_line_table
/// lays it out (records in tile order, masks of canonical lines, entries' counts in {1, 3..8}
/// and at most `field.layers`, offsets that add up, the interior hits all used). False with what
/// is wrong.
bool check_field_tables(const GeometryField& field, std::string& why);

/// A layered table (the layout of versions 1 and 2): `layers` tables of (6N^2)^2 uvs, index
/// (layer * 6N^2 + entry) * 6N^2 + exit. Fills `field` (N, layers set by the caller) with its
/// lines: the nearest hits as they are, each line's hits merged from both of its ends.
void compact_layered_table(const std::vector<glm::vec2>& table, int layers, GeometryField& field);

}  // namespace gfield
