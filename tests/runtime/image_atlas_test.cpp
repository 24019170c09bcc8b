// Geometry images sharing texture-array layers (runtime/image_atlas.hpp): every slot inside its
// layer, no two overlapping, and as few layers as the sizes allow in the cases --size auto makes.

#include <gtest/gtest.h>

#include "runtime/image_atlas.hpp"

namespace gfield {
namespace {

/// Every slot lies inside a side x side layer below `layers`, and no two slots overlap.
void expect_valid(const std::vector<int>& sizes, int side, const std::vector<AtlasSlot>& slots,
                  int layers) {
  ASSERT_EQ(slots.size(), sizes.size());
  for (size_t a = 0; a < slots.size(); ++a) {
    const AtlasSlot& s = slots[a];
    EXPECT_GE(s.layer, 0);
    EXPECT_LT(s.layer, layers);
    EXPECT_GE(s.x, 0);
    EXPECT_GE(s.y, 0);
    EXPECT_LE(s.x + sizes[a], side);
    EXPECT_LE(s.y + sizes[a], side);
    for (size_t b = a + 1; b < slots.size(); ++b) {
      const AtlasSlot& t = slots[b];
      const bool apart = s.layer != t.layer || s.x + sizes[a] <= t.x || t.x + sizes[b] <= s.x ||
                         s.y + sizes[a] <= t.y || t.y + sizes[b] <= s.y;
      EXPECT_TRUE(apart) << "images " << a << " and " << b << " overlap";
    }
  }
}

TEST(ImageAtlas, SmallerImagesShareALayer) {
  // Nine 512^2 images and one 1024^2: 1 + 3 layers (the 1024^2 alone, four 512^2 per layer).
  std::vector<int> sizes(9, 512);
  sizes.insert(sizes.begin() + 4, 1024);
  int layers = 0;
  const std::vector<AtlasSlot> slots = pack_image_atlas(sizes, 1024, layers);
  expect_valid(sizes, 1024, slots, layers);
  EXPECT_EQ(layers, 4);
  EXPECT_EQ(slots[4].layer, 0);  // the largest first
  EXPECT_EQ(slots[4].x, 0);
  EXPECT_EQ(slots[4].y, 0);
}

TEST(ImageAtlas, OneSizeIsOneLayerEach) {
  const std::vector<int> sizes = {512, 512, 512};
  int layers = 0;
  const std::vector<AtlasSlot> slots = pack_image_atlas(sizes, 512, layers);
  expect_valid(sizes, 512, slots, layers);
  EXPECT_EQ(layers, 3);
  for (int m = 0; m < 3; ++m)
    EXPECT_EQ(slots[size_t(m)].layer, m);  // in input order
}

TEST(ImageAtlas, AnySizesFitWithoutOverlap) {
  const std::vector<int> sizes = {300, 1000, 8, 257, 640, 123, 999, 64, 512, 1000, 2, 700};
  int layers = 0;
  const std::vector<AtlasSlot> slots = pack_image_atlas(sizes, 1000, layers);
  expect_valid(sizes, 1000, slots, layers);
  long long area = 0;
  for (int n : sizes)
    area += (long long)n * n;
  EXPECT_GE((long long)layers * 1000 * 1000, area);
  EXPECT_LE(layers, int(sizes.size()));
  int none = -1;
  EXPECT_TRUE(pack_image_atlas({}, 16, none).empty());
  EXPECT_EQ(none, 0);
}

}  // namespace
}  // namespace gfield
