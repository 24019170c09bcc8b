// The portable distributions: their numbers come from the engine's bits alone (the C++
// standard pins std::mt19937_64's 10000th output), their ranges and their moments.

#include "preprocess/portable_random.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace gfield {
namespace {

TEST(PortableRandom, UniformsAreTheEnginesBits) {
  std::mt19937_64 rng;  // default seed: the standard fixes its 10000th number
  rng.discard(9999);
  const uint64_t bits = 9981545732273789042ull;
  std::mt19937_64 copy = rng;
  EXPECT_EQ(UnitUniform()(rng), double(bits >> 11) * 0x1.0p-53);
  EXPECT_EQ(UnitUniformFloat()(copy), float(bits >> 40) * 0x1.0p-24f);
}

TEST(PortableRandom, IntegersCoverTheirRangeEvenly) {
  std::mt19937_64 rng(3);
  const UniformInt die{1, 6};
  std::array<int, 6> counts{};
  for (int k = 0; k < 60000; ++k) {
    const int v = die(rng);
    ASSERT_GE(v, 1);
    ASSERT_LE(v, 6);
    ++counts[size_t(v - 1)];
  }
  for (int c : counts)
    EXPECT_NEAR(c, 10000, 400);  // 4 standard deviations
  const UniformInt one{7, 7};
  EXPECT_EQ(one(rng), 7);
}

TEST(PortableRandom, NormalsHaveMeanZeroAndVarianceOne) {
  std::mt19937_64 rng(5);
  const StandardNormal gauss;
  double sum = 0.0, squares = 0.0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double x = gauss(rng);
    ASSERT_TRUE(std::isfinite(x));
    sum += x;
    squares += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(squares / n, 1.0, 0.01);
}

}  // namespace
}  // namespace gfield
