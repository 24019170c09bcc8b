#include "gfield/field_lines.hpp"

#include <algorithm>
#include <utility>

#include "gfield/check.hpp"
#include "gfield/glsl_names.hpp"
#include "gfield/gpu_contract.hpp"
#include "glsl_field_tables.hpp"

namespace gfield {
namespace {

using namespace gfield::glsl;  // the GLSL vocabulary of field_lines.glsl
using namespace gfield::gpu;   // and the contract's addressing

/// shaders/lib/field_lines.glsl compiled as C++ over the CPU copy of a field.
struct GlslFieldLines : GlslFieldTables {
#include "gfield/glsl_begin.hpp"

#include "../../shaders/lib/field_lines.glsl"

#include "gfield/glsl_end.hpp"
};

int face_of(int n, int sample) {
  return face_sample(sample, n).face;
}

/// The sample at `column` of `row`'s row (the inverse of field_column).
int sample_at_column(int n, int row, int column) {
  const int per_face = n * n;
  const int face = column / per_face;
  return (face + (face >= face_of(n, row) ? 1 : 0)) * per_face + column % per_face;
}

bool is_uv(glm::vec2 uv) {
  return uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f;
}

bool is_miss(glm::vec2 uv) {
  return uv.x == kFieldMiss && uv.y == kFieldMiss;
}

/// The record of one tile of the line table, as pack_line_table writes it.
struct TileRecord {
  uint64_t mask = 0;
  uint32_t first_entry = 0;     ///< half-word index of the tile's first entry
  uint32_t first_interior = 0;  ///< index of its first interior hit
};

/// The 16-bit entry of a line: its count and its interior hits' offset within the tile.
uint32_t line_entry(int count, uint32_t offset) {
  // A tile's 64 lines hold at most 64 * (kMaxLineHits - 2) interior hits: 12 bits of offset.
  GF_CHECK(count >= 1 && count <= kMaxLineHits && offset < 4096u, "a line entry out of its bits");
  return uint32_t(count) | (offset << 4);
}

/// Appends the halves of `entries` two per word (the first in the low half).
void append_entries(const std::vector<uint16_t>& entries, std::vector<uint32_t>& words) {
  for (size_t h = 0; h < entries.size(); h += 2) {
    const uint32_t high = h + 1 < entries.size() ? entries[h + 1] : 0u;
    words.push_back(uint32_t(entries[h]) | (high << 16));
  }
}

/// The hits of one end of a layered table's line: `layers` at most, in order from that end.
LineHits layered_hits(const std::vector<glm::vec2>& table, int layers, size_t side, size_t entry,
                      size_t exit) {
  LineHits hits;
  for (int layer = 0; layer < layers; ++layer) {
    const glm::vec2 uv = table[(size_t(layer) * side + entry) * side + exit];
    if (uv.x < 0.0f) {
      break;
    }
    hits.uv[size_t(hits.count++)] = uv;
  }
  return hits;
}

/// One line's hits from both ends of a layered table (`from_low`, and `from_high` reversed into
/// the same order): the longer list where either holds the whole line (fewer than `layers`);
/// else both, the hits they share (the longest suffix of one equal to a prefix of the other)
/// once.
LineHits merge_ends(const LineHits& from_low, const LineHits& from_high, int layers) {
  LineHits high = from_high;
  std::reverse(high.uv.begin(), high.uv.begin() + high.count);
  if (from_low.count < layers || high.count < layers) {
    return from_low.count >= high.count ? from_low : high;
  }
  int overlap = layers;
  while (overlap > 0 && !std::equal(high.uv.begin(), high.uv.begin() + overlap,
                                    from_low.uv.begin() + (layers - overlap))) {
    --overlap;
  }
  LineHits hits = from_low;
  for (int k = overlap; k < layers && hits.count < kMaxLineHits; ++k) {
    hits.uv[size_t(hits.count++)] = high.uv[size_t(k)];
  }
  return hits;
}

/// check_field_tables for the nearest and interior hits' values.
bool check_hit_values(const GeometryField& field, std::string& why) {
  const size_t columns = size_t(field_columns(field));
  for (size_t k = 0; k < field.nearest.size(); ++k) {
    const glm::vec2 uv = field.nearest[k];
    if (!is_uv(uv) && !is_miss(uv)) {
      why = "nearest hit (" + std::to_string(uv.x) + ", " + std::to_string(uv.y) + ") at entry " +
            std::to_string(k / columns) + ", column " + std::to_string(k % columns) +
            " is neither a uv in [0,1]^2 nor a miss";
      return false;
    }
  }
  for (size_t k = 0; k < field.interior.size(); ++k) {
    if (!is_uv(field.interior[k])) {
      why = "interior hit " + std::to_string(k) + " (" + std::to_string(field.interior[k].x) +
            ", " + std::to_string(field.interior[k].y) + ") is not a uv in [0,1]^2";
      return false;
    }
  }
  return true;
}

/// check_field_tables for the lines of one tile's record at word `w` (tile `tile`); `entry` and
/// `interior` count the entries and interior hits of the tiles before it.
bool check_record(const GeometryField& field, int tile, size_t w, uint32_t entries_start,
                  uint32_t& entry, uint32_t& interior, std::string& why) {
  const int n = field.samples_per_side;
  const std::vector<uint32_t>& words = field.lines;
  const uint64_t mask = uint64_t(words[w]) | (uint64_t(words[w + 1]) << 32);
  const std::string where = "line table, tile " + std::to_string(tile) + ": ";
  if (mask == 0) {
    why = where + "its record marks no line";
    return false;
  }
  if (words[w + 2] != entries_start + entry || words[w + 3] != interior) {
    why = where + "its record's first entry " + std::to_string(words[w + 2]) +
          " or first interior hit " + std::to_string(words[w + 3]) + " is not " +
          std::to_string(entries_start + entry) + " or " + std::to_string(interior);
    return false;
  }
  const int tile_columns = gpu::gf_field_tile_columns(n);
  for (int slot = 0; slot < 64; ++slot) {
    if (((mask >> slot) & 1u) == 0) {
      continue;
    }
    const int row = tile / tile_columns * FIELD_TILE + slot / FIELD_TILE;
    const int column = tile % tile_columns * FIELD_TILE + slot % FIELD_TILE;
    if (row >= sample_count(n) || column >= field_columns(field) ||
        sample_at_column(n, row, column) <= row) {
      why = where + "slot " + std::to_string(slot) +
            " marks a line outside the table or not stored from its lower sample";
      return false;
    }
    const size_t half = size_t(entries_start) + entry;
    if (half / 2 >= words.size()) {
      why = where + "its entries run past the table's " + std::to_string(words.size()) + " words";
      return false;
    }
    const uint32_t bits = (words[half / 2] >> (16 * (half % 2))) & 0xFFFFu;
    const int count = int(bits & 15u);
    if (count < 1 || count == 2 || count > kMaxLineHits || bits >> 4 != interior - words[w + 3]) {
      why = where + "the line of slot " + std::to_string(slot) + " holds " + std::to_string(count) +
            " hits at offset " + std::to_string(bits >> 4) + " (expected 1 or 3 to " +
            std::to_string(kMaxLineHits) + " hits, at offset " +
            std::to_string(interior - words[w + 3]) + ")";
      return false;
    }
    interior += uint32_t(std::max(0, count - 2));
    ++entry;
  }
  return true;
}

}  // namespace

glm::vec2 field_uv(const GeometryField& field, int entry, int exit, int layer) {
  const int n = field.samples_per_side;
  GF_DCHECK(entry >= 0 && entry < field_side(field) && exit >= 0 && exit < field_side(field) &&
                layer >= 0,
            "entry or exit outside the field, or a negative layer");
  if (face_of(n, entry) == face_of(n, exit)) {
    return glm::vec2(kFieldNoRay);
  }
  GlslFieldLines reader{{field}};
  GlslFieldLines::GfLineHits line = reader.gf_line_unread();
  return reader.gf_line_hit(entry, exit, layer, line);
}

int field_column(int samples_per_side, int entry, int exit) {
  return gpu::gf_field_column(samples_per_side, entry, exit);
}

void reset_field_tables(GeometryField& field) {
  field.nearest.clear();  // a field built before keeps its memory, but its values are not copied
  field.nearest.resize(field_nearest_size(field));
  field.lines.clear();
  field.interior.clear();
}

void store_line(GeometryField& field, int low, int high, const LineHits& hits,
                std::vector<TableLine>& table_lines) {
  const int n = field.samples_per_side;
  const int column = field_column(n, low, high);
  const bool hit = hits.count > 0;
  field.nearest[field_nearest_index(field, low, column)] = hit ? hits.uv[0] : glm::vec2(kFieldMiss);
  field.nearest[field_nearest_index(field, high, field_column(n, high, low))] =
      hit ? hits.uv[size_t(hits.count - 1)] : glm::vec2(kFieldMiss);
  if (hits.count == 0 || hits.count == 2) {
    return;
  }
  TableLine& line = table_lines.emplace_back();
  line.low = uint32_t(low);
  line.column = uint32_t(column);
  line.count = hits.count;
  for (int k = 1; k + 1 < hits.count; ++k) {
    line.interior[size_t(k - 1)] = hits.uv[size_t(k)];
  }
}

void pack_line_table(std::vector<TableLine>& table_lines, GeometryField& field) {
  const int n = field.samples_per_side;
  // The lines in tile and slot order: their keys sorted (16 bytes each, not the lines' 64).
  std::vector<std::pair<uint64_t, uint32_t>> order(table_lines.size());
  for (size_t k = 0; k < table_lines.size(); ++k) {
    const TableLine& l = table_lines[k];
    const int low = int(l.low), column = int(l.column);
    order[k] = {uint64_t(gpu::gf_field_tile(n, low, column)) << 6 |
                    uint64_t(gpu::gf_field_tile_slot(low, column)),
                uint32_t(k)};
  }
  std::sort(order.begin(), order.end());
  const size_t tiles = size_t(gpu::gf_field_tiles(n));
  std::vector<TileRecord> records;
  std::vector<uint16_t> entries;
  field.lines.assign(tiles, 0u);
  field.interior.clear();
  int most = 0;
  for (size_t i = 0; i < order.size();) {
    const uint64_t tile = order[i].first >> 6;
    TileRecord& record = records.emplace_back();
    record.first_entry = uint32_t(entries.size());
    record.first_interior = uint32_t(field.interior.size());
    field.lines[size_t(tile)] = uint32_t(tiles + 4 * (records.size() - 1));
    for (; i < order.size() && order[i].first >> 6 == tile; ++i) {
      const TableLine& line = table_lines[order[i].second];
      record.mask |= uint64_t(1) << (order[i].first & 63u);
      const uint32_t offset = uint32_t(field.interior.size()) - record.first_interior;
      entries.push_back(uint16_t(line_entry(line.count, offset)));
      field.interior.insert(field.interior.end(), line.interior.begin(),
                            line.interior.begin() + std::max(0, line.count - 2));
      most = std::max(most, line.count);
    }
  }
  const uint32_t entries_start = uint32_t(2 * (tiles + 4 * records.size()));
  for (const TileRecord& r : records) {
    field.lines.push_back(uint32_t(r.mask));
    field.lines.push_back(uint32_t(r.mask >> 32));
    field.lines.push_back(entries_start + r.first_entry);
    field.lines.push_back(r.first_interior);
  }
  append_entries(entries, field.lines);
  const bool any_hit = std::any_of(field.nearest.begin(), field.nearest.end(),
                                   [](glm::vec2 uv) { return uv.x >= 0.0f; });
  field.layers = std::max(any_hit ? 2 : 1, most);
}

void layered_pair(const GeometryField& field, int entry, int exit, int layers, glm::vec2* uv) {
  const int n = field.samples_per_side;
  const bool no_ray = face_of(n, entry) == face_of(n, exit);
  const LineHits hits = no_ray ? LineHits{} : line_hits(field, entry, exit);
  for (int layer = 0; layer < layers; ++layer) {
    uv[layer] = no_ray               ? glm::vec2(kFieldNoRay)
                : layer < hits.count ? hits.uv[size_t(layer)]
                                     : glm::vec2(kFieldMiss);
  }
}

LineHits line_hits(const GeometryField& field, int entry, int exit) {
  LineHits hits;
  GlslFieldLines reader{{field}};
  GlslFieldLines::GfLineHits line = reader.gf_line_unread();
  for (int layer = 0; layer < kMaxLineHits; ++layer) {
    const glm::vec2 uv = reader.gf_line_hit(entry, exit, layer, line);
    if (uv.x < 0.0f) {
      break;
    }
    hits.uv[size_t(hits.count++)] = uv;
  }
  return hits;
}

}  // namespace gfield

namespace gfield {

bool check_field_tables(const GeometryField& field, std::string& why) {
  const int n = field.samples_per_side;
  if (field.nearest.size() != field_nearest_size(field) || field.layers < 1 ||
      field.layers > kMaxLineHits) {
    why = "the nearest-hit table or the layers do not match N = " + std::to_string(n);
    return false;
  }
  if (!check_hit_values(field, why)) {
    return false;
  }
  const size_t tiles = size_t(gpu::gf_field_tiles(n));
  const std::vector<uint32_t>& words = field.lines;
  const size_t records = words.size() < tiles
                             ? 0
                             : tiles - size_t(std::count(words.begin(), words.begin() + tiles, 0u));
  if (words.size() < tiles + 4 * records) {
    why = "the line table has " + std::to_string(words.size()) + " words, fewer than its " +
          std::to_string(tiles) + " tiles and " + std::to_string(records) + " records need";
    return false;
  }
  const uint32_t entries_start = uint32_t(2 * (tiles + 4 * records));
  uint32_t entry = 0, interior = 0;
  size_t next_record = tiles;
  for (size_t tile = 0; tile < tiles; ++tile) {
    if (words[tile] == 0) {
      continue;
    }
    if (words[tile] != next_record) {
      why = "line table, tile " + std::to_string(tile) + ": its record at word " +
            std::to_string(words[tile]) + ", expected " + std::to_string(next_record) +
            " (records in tile order, 4 words each)";
      return false;
    }
    if (!check_record(field, int(tile), next_record, entries_start, entry, interior, why)) {
      return false;
    }
    next_record += 4;
  }
  const size_t expected_words = tiles + 4 * records + (size_t(entry) + 1) / 2;
  if (words.size() != expected_words || interior != field.interior.size()) {
    why = "the line table has " + std::to_string(words.size()) + " words and " +
          std::to_string(field.interior.size()) + " interior hits, its entries need " +
          std::to_string(expected_words) + " and " + std::to_string(interior);
    return false;
  }
  return true;
}

void compact_layered_table(const std::vector<glm::vec2>& table, int layers, GeometryField& field) {
  const int n = field.samples_per_side;
  const size_t side = size_t(sample_count(n));
  reset_field_tables(field);
  std::vector<TableLine> table_lines;
  for (size_t low = 0; low < side; ++low) {
    for (size_t high = low + 1; high < side; ++high) {
      if (face_of(n, int(low)) == face_of(n, int(high))) {
        continue;
      }
      const LineHits hits = merge_ends(layered_hits(table, layers, side, low, high),
                                       layered_hits(table, layers, side, high, low), layers);
      store_line(field, int(low), int(high), hits, table_lines);
      // The nearest hits as the table holds them (a line may hit from one end only).
      const glm::vec2 a = table[low * side + high], b = table[high * side + low];
      field.nearest[field_nearest_index(field, int(low), field_column(n, int(low), int(high)))] =
          a.x < 0.0f ? glm::vec2(kFieldMiss) : a;
      field.nearest[field_nearest_index(field, int(high), field_column(n, int(high), int(low)))] =
          b.x < 0.0f ? glm::vec2(kFieldMiss) : b;
    }
  }
  pack_line_table(table_lines, field);
  field.layers = layers;
}

}  // namespace gfield
