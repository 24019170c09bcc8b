// PSNR and SSIM against closed-form answers.

#include <gtest/gtest.h>

#include <cmath>

#include "gfield/image_metrics.hpp"

namespace gfield {
namespace {

Image pattern(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const float v = 0.5f + 0.4f * std::sin(0.7f * float(x)) * std::cos(0.45f * float(y));
      image.at(x, y) = glm::vec3(v, 1.0f - v, 0.5f * v);
    }
  }
  return image;
}

TEST(ImageMetrics, IdenticalImages) {
  const Image a = pattern(24, 16);
  const ImageComparison c = compare_images(a, a);
  EXPECT_TRUE(std::isinf(c.psnr));
  EXPECT_NEAR(c.ssim, 1.0, 1e-9);
  EXPECT_EQ(c.pixels, 24u * 16u);
  EXPECT_EQ(c.max_abs_error, 0.0);
}

TEST(ImageMetrics, ConstantOffsetGivesKnownPsnrAndSsim) {
  // Offset 0.01 everywhere: MSE = 1e-4, PSNR = 40 dB exactly (peak 1).
  const Image a(16, 16, glm::vec3(0.3f));
  const Image b(16, 16, glm::vec3(0.31f));
  const ImageComparison c = compare_images(a, b);
  EXPECT_NEAR(c.psnr, 40.0, 1e-4);
  EXPECT_NEAR(c.max_abs_error, 0.01, 1e-6);
  // Constant images: variances 0, SSIM = (2 mx my + C1) / (mx^2 + my^2 + C1).
  const double c1 = 1e-4, mx = 0.3f, my = 0.31f;
  EXPECT_NEAR(c.ssim, (2 * mx * my + c1) / (mx * mx + my * my + c1), 1e-6);
  EXPECT_NEAR(psnr_from_mse(1e-2), 20.0, 1e-12);
}

TEST(ImageMetrics, ANotANumberPixelMakesEveryErrorNotANumber) {
  const Image a(8, 8, glm::vec3(0.3f));
  Image b(8, 8, glm::vec3(0.31f));
  b.at(3, 2) = glm::vec3(0.31f, std::nanf(""), 0.31f);
  const ImageComparison c = compare_images(a, b);
  EXPECT_TRUE(std::isnan(c.max_abs_error));
  EXPECT_TRUE(std::isnan(c.mse));
  EXPECT_TRUE(std::isnan(c.psnr));
}

TEST(ImageMetrics, SsimPenalisesStructureNotJustError) {
  const Image a = pattern(32, 32);
  Image shifted = a, noisy = a;
  for (auto& p : shifted.pixels)
    p += glm::vec3(0.02f);
  // Noise of the same mean squared error as the shift, with no structure.
  for (size_t i = 0; i < noisy.pixels.size(); ++i) {
    noisy.pixels[i] += glm::vec3((i * 7919u) % 2 ? 0.02f : -0.02f);
  }
  const ImageComparison cs = compare_images(a, shifted), cn = compare_images(a, noisy);
  EXPECT_NEAR(cs.psnr, cn.psnr, 1e-3);
  EXPECT_GT(cs.ssim, cn.ssim);
  EXPECT_LT(cn.ssim, 0.99);
  // Symmetric.
  EXPECT_NEAR(compare_images(noisy, a).ssim, cn.ssim, 1e-12);
}

TEST(ImageMetrics, MaskRestrictsThePixels) {
  const Image a(8, 8, glm::vec3(0.5f));
  Image b = a;
  b.at(1, 1) = glm::vec3(1.0f);  // one bad pixel, outside the mask
  PixelMask mask(64, false);
  for (int x = 4; x < 8; ++x)
    mask[size_t(6 * 8 + x)] = true;
  const ImageComparison masked = compare_images(a, b, mask);
  EXPECT_EQ(masked.pixels, 4u);
  EXPECT_TRUE(std::isinf(masked.psnr));
  EXPECT_EQ(masked.max_abs_error, 0.0);
  const ImageComparison all = compare_images(a, b);
  EXPECT_NEAR(all.mse, 0.25 / 64.0, 1e-9);
  // A mask made from an image.
  Image m(8, 8);
  m.at(3, 2) = glm::vec3(1.0f);
  const PixelMask from = mask_from_image(m);
  EXPECT_EQ(std::count(from.begin(), from.end(), true), 1);
  EXPECT_TRUE(from[2 * 8 + 3]);
}

TEST(ImageMetrics, SizeMismatchAndHeatmap) {
  EXPECT_EQ(compare_images(Image(4, 4), Image(4, 5)).pixels, 0u);
  const Image a(4, 4, glm::vec3(0.2f));
  Image b = a;
  b.at(2, 1) = glm::vec3(0.7f);
  const Image heat = error_heatmap(a, b, 0.5);
  EXPECT_EQ(heat.at(0, 0), glm::vec3(0.0f));
  EXPECT_EQ(heat.at(2, 1), glm::vec3(1.0f));
}

}  // namespace
}  // namespace gfield
