// The compact field's lines (gfield/field_lines.hpp): every line stored reads back, from both of
// its samples, exactly as stored (the line table's addressing, masks, entries and interior
// offsets); the packed table passes its own check; layered tables convert with each line's hits
// merged from both ends.

#include "gfield/field_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "gfield/box.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

bool same_face(int n, int a, int b) {
  return a / (n * n) == b / (n * n);
}

/// A compact field of N = n whose lines hold a random count of random hits (0 to kMaxLineHits,
/// the counts of real fields: mostly 0 and 2), and the hits each line got (index low * S + high).
GeometryField random_field(int n, unsigned seed, std::vector<LineHits>& stored) {
  GeometryField field;
  field.samples_per_side = n;
  reset_field_tables(field);
  const int side = sample_count(n);
  stored.assign(size_t(side) * size_t(side), LineHits{});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::discrete_distribution<int> count({40, 2, 40, 3, 8, 2, 2, 1, 2});
  std::vector<TableLine> table_lines;
  for (int low = 0; low < side; ++low) {
    for (int high = low + 1; high < side; ++high) {
      if (same_face(n, low, high)) {
        continue;
      }
      LineHits& hits = stored[size_t(low) * size_t(side) + size_t(high)];
      hits.count = count(rng);
      for (int k = 0; k < hits.count; ++k) {
        hits.uv[size_t(k)] = {u(rng), u(rng)};
      }
      store_line(field, low, high, hits, table_lines);
    }
  }
  pack_line_table(table_lines, field);
  return field;
}

TEST(FieldLines, EveryLineReadsBackFromBothSamples) {
  for (int n : {1, 3, 4}) {
    std::vector<LineHits> stored;
    const GeometryField field = random_field(n, 11u + unsigned(n), stored);
    std::string why;
    ASSERT_TRUE(check_field_tables(field, why)) << why;
    int most = 2;
    for (const LineHits& hits : stored) {
      most = std::max(most, hits.count);
    }
    EXPECT_EQ(field.layers, most);
    const int side = sample_count(n);
    for (int a = 0; a < side; ++a) {
      for (int b = 0; b < side; ++b) {
        if (same_face(n, a, b)) {
          EXPECT_EQ(field_uv(field, a, b), glm::vec2(kFieldNoRay));
          continue;
        }
        const LineHits& want =
            stored[size_t(std::min(a, b)) * size_t(side) + size_t(std::max(a, b))];
        const LineHits got = line_hits(field, a, b);
        ASSERT_EQ(got.count, want.count) << n << ": " << a << " -> " << b;
        for (int k = 0; k < want.count; ++k) {
          const int from_low = a < b ? k : want.count - 1 - k;
          ASSERT_EQ(got.uv[size_t(k)], want.uv[size_t(from_low)]) << a << " -> " << b << " " << k;
          ASSERT_EQ(field_uv(field, a, b, k), got.uv[size_t(k)]);
        }
        EXPECT_EQ(field_uv(field, a, b, want.count), glm::vec2(kFieldMiss));
      }
    }
  }
}

TEST(FieldLines, OnlyLinesOfOneOrOfThreeAndMoreHitsTakeTableSpace) {
  std::vector<LineHits> stored;
  const GeometryField field = random_field(3, 5u, stored);
  size_t table_lines = 0, interior = 0;
  for (const LineHits& hits : stored) {
    table_lines += hits.count == 1 || hits.count >= 3;
    interior += size_t(std::max(0, hits.count - 2));
  }
  EXPECT_EQ(field.interior.size(), interior);
  const size_t tiles = size_t(gpu::gf_field_tiles(3));
  size_t records = 0;
  for (size_t t = 0; t < tiles; ++t) {
    records += field.lines[t] != 0;
  }
  // The tile table, 4 words per record, 16 bits per table line.
  EXPECT_EQ(field.lines.size(), tiles + 4 * records + (table_lines + 1) / 2);
}

TEST(FieldLines, LayeredTablesMergeTheHitsOfBothEnds) {
  const int n = 1, side = 6;  // samples 0..5, one per face
  const size_t count = size_t(side) * size_t(side);
  const int layers = 2;
  std::vector<glm::vec2> table(count * layers, glm::vec2(kFieldMiss));
  const auto set = [&](int entry, int exit, std::initializer_list<glm::vec2> hits) {
    int layer = 0;
    for (glm::vec2 uv : hits) {
      table[size_t(layer++) * count + size_t(entry) * side + size_t(exit)] = uv;
    }
  };
  const glm::vec2 h1(0.1f), h2(0.2f), h3(0.3f), h4(0.4f);
  set(0, 1, {h1, h2});  // 2 hits, both seen from each end
  set(1, 0, {h2, h1});
  set(0, 2, {h1, h2});  // 3 hits: the ends share h2
  set(2, 0, {h3, h2});
  set(0, 3, {h1, h2});  // 4 hits or more: nothing shared
  set(3, 0, {h4, h3});
  set(0, 4, {h1});  // 1 hit
  set(4, 0, {h1});
  set(0, 5, {h1});  // seen from one end only (a grazing ray of an old single-layer build)
  for (int a = 0; a < side; ++a) {
    table[size_t(a) * side + size_t(a)] = table[count + size_t(a) * side + size_t(a)] =
        glm::vec2(kFieldNoRay);
  }
  GeometryField field;
  field.samples_per_side = n;
  compact_layered_table(table, layers, field);
  std::string why;
  ASSERT_TRUE(check_field_tables(field, why)) << why;
  EXPECT_EQ(field.layers, layers);
  const auto hits = [&](int a, int b) {
    const LineHits h = line_hits(field, a, b);
    return std::vector<glm::vec2>(h.uv.begin(), h.uv.begin() + h.count);
  };
  using V = std::vector<glm::vec2>;
  EXPECT_EQ(hits(0, 1), (V{h1, h2}));
  EXPECT_EQ(hits(0, 2), (V{h1, h2, h3}));
  EXPECT_EQ(hits(2, 0), (V{h3, h2, h1}));
  EXPECT_EQ(hits(0, 3), (V{h1, h2, h3, h4}));
  EXPECT_EQ(hits(0, 4), (V{h1}));
  EXPECT_EQ(hits(0, 5), (V{h1}));
  EXPECT_EQ(field_uv(field, 5, 0), glm::vec2(kFieldMiss));  // as the table held it
}

}  // namespace
}  // namespace gfield
