#pragma once
// Where the scene's geometry images lie in the texture arrays: layers of side x side texels, side
// = the largest image's n; smaller images share layers (four 512^2 images in one 1024^2 layer),
// so that one 1024^2 image does not make every 512^2 one pay 1024^2 texels.

#include <vector>

namespace gfield {

/// Texels [x, x + n) x [y, y + n) of array layer `layer` hold an n x n image.
struct AtlasSlot {
  int layer = 0;
  int x = 0;
  int y = 0;
};

/// Slots (one per entry of `sizes`, texels per side, each in [1, side]) in layers of side x side
/// texels: shelves, largest image first (ties in input order), each image on the first shelf of
/// the first layer with room. `layers` receives the layer count (0 for no images).
std::vector<AtlasSlot> pack_image_atlas(const std::vector<int>& sizes, int side, int& layers);

}  // namespace gfield
