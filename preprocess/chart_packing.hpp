#pragma once
// Packing square charts into one geometry image: each chart gets a square of texels whose side is
// proportional to the square root of its surface area (equal texel density), charts a gutter of
// texels apart, placed on shelves (largest first) at the largest scale that fits.

#include <string>
#include <vector>

namespace gfield {

/// Texels [x, x + size) x [y, y + size) of an n x n image (column x, scanline y).
struct ChartRect {
  int x = 0;
  int y = 0;
  int size = 0;
};

/// Smallest chart side in texels.
inline constexpr int kMinChartTexels = 4;

/// Rects for charts of surface `areas` in an `image_size` square image, `gutter` texels apart. One
/// chart gets the whole image. False with an error when even kMinChartTexels squares do not fit.
bool pack_charts(const std::vector<double>& areas, int image_size, int gutter,
                 std::vector<ChartRect>& rects, std::string& error);

}  // namespace gfield
