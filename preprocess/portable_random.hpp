#pragma once
// Random numbers that are the same from the same seed with every standard library: std::mt19937_64
// is specified bit for bit, the standard's distributions are not (libstdc++ and libc++ draw
// different numbers from one engine). verify's ray families and the image's error samples use
// these, so their figures are reproducible across toolchains.

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace gfield {

/// Uniform double in [0, 1): the engine's top 53 bits.
struct UnitUniform {
  double operator()(std::mt19937_64& rng) const { return double(rng() >> 11) * 0x1.0p-53; }
};

/// Uniform float in [0, 1): the engine's top 24 bits.
struct UnitUniformFloat {
  float operator()(std::mt19937_64& rng) const { return float(rng() >> 40) * 0x1.0p-24f; }
};

/// Uniform integer in [lo, hi] (lo <= hi), without modulo bias (rejection).
struct UniformInt {
  int lo = 0;
  int hi = 0;
  int operator()(std::mt19937_64& rng) const {
    const uint64_t range = uint64_t(int64_t(hi) - int64_t(lo)) + 1;
    const uint64_t limit =
        std::numeric_limits<uint64_t>::max() - std::numeric_limits<uint64_t>::max() % range;
    uint64_t x = rng();
    while (x >= limit)
      x = rng();
    return int(int64_t(lo) + int64_t(x % range));
  }
};

/// Standard normal float (Box-Muller, one value per call).
struct StandardNormal {
  float operator()(std::mt19937_64& rng) const {
    const UnitUniform unit;
    const double u1 = 1.0 - unit(rng);  // (0, 1]: the logarithm stays finite
    const double u2 = unit(rng);
    return float(std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2));
  }
};

}  // namespace gfield
