// Reading a compact geometry field (contract.glsl, "The compact geometry field"): the hits of one
// line, from either of its samples.
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md; float),
// included by core/src/field_lines.cpp and
// core/src/field_lookup.cpp (inside structs whose members supply the fetches below) and by the
// runtime's shaders, after contract.glsl and before field_lookup.glsl. The includer defines:
//   int  gf_samples_per_side();                        N of the field
//   vec2 gf_field_nearest_texel(int entry, int column);  the nearest-hit table's uv (< 0: miss)
//   uint gf_field_word(int i);                         word i of the line table
//   vec2 gf_field_interior_texel(int i);               interior hit i (a uv)

// The line through a pair of samples as read from one of them: its hit count and where its
// interior hits start. count < 0: not read yet (gf_line_unread).
struct GfLineHits {
  int count;
  int interior;
  bool from_high;  // read from the higher sample: the interior hits run backwards
};

GfLineHits gf_line_unread() {
  GfLineHits line;
  line.count = -1;
  line.interior = 0;
  line.from_high = false;
  return line;
}

// Reads the line (entry, exit) from the line table: a line without an entry holds 2 hits, or
// none (then its nearest hits are misses).
GfLineHits gf_read_line(int entry, int exit) {
  int n = gf_samples_per_side();
  int low = min(entry, exit);
  int column = gf_field_column(n, low, max(entry, exit));
  GfLineHits line;
  line.count = 2;
  line.interior = 0;
  line.from_high = entry > exit;
  int record = int(gf_field_word(gf_field_tile(n, low, column)));
  if (record == 0) {
    return line;
  }
  int slot = gf_field_tile_slot(low, column);
  int bit = slot % 32;
  uint mask = gf_field_word(record + slot / 32);  // the half of the tile's mask holding the slot
  if (((mask >> uint(bit)) & 1u) == 0u) {
    return line;
  }
  int rank = int(bitCount(mask & ((1u << uint(bit)) - 1u)));
  if (slot >= 32) {
    rank += int(bitCount(gf_field_word(record)));
  }
  int half_index = int(gf_field_word(record + 2)) + rank;
  uint entry_bits = (gf_field_word(half_index / 2) >> uint(16 * (half_index % 2))) & 65535u;
  line.count = int(entry_bits & 15u);
  line.interior = int(gf_field_word(record + 3)) + int(entry_bits >> 4u);
  return line;
}

// Hit `layer` (0: the nearest) of the line from `entry` towards `exit` (on different faces): its
// uv, or (-1, -1) past the line's last hit. `line` is read on the first layer past 0 and kept.
// One fetch of the nearest-hit table for either end (each fetch is code that llvmpipe runs for
// every lane of a group where one needs it).
vec2 gf_line_hit(int entry, int exit, int layer, GF_INOUT(GfLineHits) line) {
  if (layer > 0 && line.count < 0) {
    line = gf_read_line(entry, exit);
  }
  if (layer > 0 && layer >= line.count) {
    return vec2(-1.0f);
  }
  if (layer == 0 || layer == line.count - 1) {
    int from = layer == 0 ? entry : exit;
    int to = layer == 0 ? exit : entry;
    return gf_field_nearest_texel(from, gf_field_column(gf_samples_per_side(), from, to));
  }
  return gf_field_interior_texel(line.interior +
                                 (line.from_high ? line.count - 2 - layer : layer - 1));
}
