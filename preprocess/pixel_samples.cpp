#include "preprocess/pixel_samples.hpp"

#include <algorithm>
#include <cmath>

namespace gfield {
namespace {

/// splitmix64: the per-sample random numbers (a pure function of its input).
std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}
double unit_double(std::uint64_t x) {
  return double(x >> 11) * (1.0 / 9007199254740992.0);
}

}  // namespace

glm::ivec2 pixel_strata(int spp) {
  int nx = std::max(1, int(std::sqrt(double(spp))));
  while (spp % nx != 0)
    --nx;
  return {nx, spp / nx};
}

glm::dvec2 pixel_sample(int x, int y, int s, int width, glm::ivec2 grid, bool jitter,
                        std::uint64_t seed) {
  const int sx = s % grid.x, sy = s / grid.x;
  double jx = 0.5, jy = 0.5;
  if (jitter) {
    const std::uint64_t key =
        mix64(seed ^ mix64((std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x)) * 1024u +
                           std::uint64_t(s)));
    jx = unit_double(key);
    jy = unit_double(mix64(key));
  }
  return {double(x) + (double(sx) + jx) / double(grid.x),
          double(y) + (double(sy) + jy) / double(grid.y)};
}

}  // namespace gfield
