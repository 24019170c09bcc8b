// Area-proportional shelf packing of square charts.

#include "preprocess/chart_packing.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gfield {
namespace {

/// Shelf packing of squares (sides in texels) in the given order; false if they do not fit.
bool shelf_pack(const std::vector<int>& order, const std::vector<int>& sides, int n, int gutter,
                std::vector<ChartRect>& rects) {
  int x = 0, y = 0, shelf = 0;
  for (int c : order) {
    const int s = sides[c];
    if (s > n)
      return false;
    if (x > 0 && x + s > n) {
      y += shelf + gutter;
      x = 0;
      shelf = 0;
    }
    if (y + s > n)
      return false;
    rects[c] = {x, y, s};
    x += s + gutter;
    shelf = std::max(shelf, s);
  }
  return true;
}

}  // namespace

bool pack_charts(const std::vector<double>& areas, int image_size, int gutter,
                 std::vector<ChartRect>& rects, std::string& error) {
  const size_t count = areas.size();
  rects.assign(count, {});
  if (count == 0) {
    error = "no chart to pack";
    return false;
  }
  if (count == 1) {
    rects[0] = {0, 0, image_size};
    return true;
  }
  std::vector<double> weight(count);
  for (size_t c = 0; c < count; ++c)
    weight[c] = std::sqrt(std::max(areas[c], 0.0));
  std::vector<int> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
  const double largest = std::max(weight[order[0]], 1e-300);

  auto sides_at = [&](double scale) {
    std::vector<int> sides(count);
    for (size_t c = 0; c < count; ++c)
      sides[c] = std::max(kMinChartTexels, int(std::floor(scale * weight[c] / largest)));
    return sides;
  };
  // Largest side (texels) of the largest chart such that everything fits.
  int lo = kMinChartTexels - 1, hi = image_size;
  std::vector<ChartRect> trial(count);
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (shelf_pack(order, sides_at(mid), image_size, gutter, trial))
      lo = mid;
    else
      hi = mid - 1;
  }
  if (lo < kMinChartTexels || !shelf_pack(order, sides_at(lo), image_size, gutter, rects)) {
    error = std::to_string(count) + " charts do not fit in a " + std::to_string(image_size) +
            "^2 image (each needs at least " + std::to_string(kMinChartTexels) +
            " texels per side and a gutter of " + std::to_string(gutter) + ")";
    return false;
  }
  return true;
}

}  // namespace gfield
