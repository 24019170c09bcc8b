#include "runtime/image_atlas.hpp"

#include <algorithm>
#include <numeric>

namespace gfield {
namespace {

/// A row of images of at most `height` texels, filled from x = 0 up to `width`.
struct Shelf {
  int y = 0;
  int height = 0;
  int width = 0;
};

/// One layer: its shelves from y = 0 down to `height`.
struct Layer {
  std::vector<Shelf> shelves;
  int height = 0;
};

/// Places an n x n image in `layer` (side x side): false when there is no room.
bool place(Layer& layer, int n, int side, int index, AtlasSlot& slot) {
  for (Shelf& shelf : layer.shelves) {
    if (n <= shelf.height && shelf.width + n <= side) {
      slot = {index, shelf.width, shelf.y};
      shelf.width += n;
      return true;
    }
  }
  if (layer.height + n > side)
    return false;
  layer.shelves.push_back({layer.height, n, n});
  slot = {index, 0, layer.height};
  layer.height += n;
  return true;
}

}  // namespace

std::vector<AtlasSlot> pack_image_atlas(const std::vector<int>& sizes, int side, int& layers) {
  std::vector<size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return sizes[a] > sizes[b]; });
  std::vector<Layer> packed;
  std::vector<AtlasSlot> slots(sizes.size());
  for (size_t i : order) {
    bool placed = false;
    for (size_t l = 0; l < packed.size() && !placed; ++l)
      placed = place(packed[l], sizes[i], side, int(l), slots[i]);
    if (!placed) {
      packed.emplace_back();
      place(packed.back(), sizes[i], side, int(packed.size() - 1), slots[i]);
    }
  }
  layers = int(packed.size());
  return slots;
}

}  // namespace gfield
