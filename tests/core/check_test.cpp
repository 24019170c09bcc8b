// Checked invariants (gfield/check.hpp): GF_CHECK stops the process with its file, line,
// condition and message; GF_DCHECK does in debug and sanitizer builds only, and the index helpers
// check their indices with it.

#include "gfield/check.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gfield/geometry_field.hpp"
#include "gfield/geometry_image.hpp"

namespace gfield {
namespace {

TEST(CheckDeathTest, CheckPrintsFileLineConditionAndMessageAndAborts) {
  const std::vector<int> v = {1, 2};
  GF_CHECK(v.size() == 2, "never printed");
  EXPECT_DEATH(GF_CHECK(v.size() == 3, "a vector of " + std::to_string(v.size())),
               "check_test\\.cpp:[0-9]+: check failed: v\\.size\\(\\) == 3: a vector of 2");
}

TEST(CheckDeathTest, ComparisonsPrintBothValuesAndEvaluateEachOperandOnce) {
  int calls = 0;
  const auto next = [&] { return ++calls; };
  GF_CHECK_EQ(next(), 1, "never printed");
  GF_CHECK_LT(next(), 3, "never printed");
  GF_CHECK_GE(2.5, 2.5, "never printed");
  EXPECT_EQ(calls, 2);
  const size_t rays = 96;
  EXPECT_DEATH(GF_CHECK_EQ(rays, 95u, "every ray counted once"),
               "check_test\\.cpp:[0-9]+: check failed: rays == 95u \\(96 vs 95\\): every ray "
               "counted once");
  EXPECT_DEATH(GF_CHECK_LE(0.1 + 0.2, 0.3, "sums"),
               "0\\.1 \\+ 0\\.2 <= 0\\.3 "
               "\\(0\\.30000000000000004 vs 0\\.29999999999999999\\)");
  EXPECT_DEATH(GF_CHECK_NE(std::string("a"), "a", "names"), "\\(a vs a\\): names");
}

TEST(CheckDeathTest, DcheckEvaluatesAndFiresOnlyWhereItIsOn) {
  int evaluated = 0;
  GF_DCHECK(++evaluated == 1, "counted once where it is on");
  EXPECT_EQ(evaluated, GF_DCHECK_IS_ON);
#if GF_DCHECK_IS_ON
  EXPECT_DEATH(GF_DCHECK(evaluated == 2, "where"), "check failed: evaluated == 2: where");
#endif
}

TEST(CheckDeathTest, IndexHelpersCheckTheirIndicesWhereDchecksAreOn) {
  GeometryImage image;
  image.size = 4;
  EXPECT_EQ(texel_index(image, 3, 2), 11u);
  GeometryField field;
  field.samples_per_side = 2;
  EXPECT_EQ(field_nearest_index(field, 23, 19), 23u * 20u + 19u);
#if GF_DCHECK_IS_ON
  EXPECT_DEATH(texel_index(image, 4, 0), "texel outside the image");
  EXPECT_DEATH(texel_index(image, 0, -1), "texel outside the image");
  EXPECT_DEATH(field_nearest_index(field, 24, 0), "outside the nearest-hit table");
  EXPECT_DEATH(field_nearest_index(field, 0, 20), "outside the nearest-hit table");
#endif
}

}  // namespace
}  // namespace gfield
