// PSNR, SSIM and error heat maps.

#include "gfield/image_metrics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "gfield/file_extension.hpp"

namespace gfield {
namespace {

constexpr int kRadius = 5;  // 11 x 11 window
constexpr double kSigma = 1.5;

std::array<double, 2 * kRadius + 1> gaussian_weights() {
  std::array<double, 2 * kRadius + 1> w{};
  for (int i = -kRadius; i <= kRadius; ++i) {
    w[size_t(i + kRadius)] = std::exp(-double(i * i) / (2.0 * kSigma * kSigma));
  }
  return w;
}

/// Separable Gaussian blur of a scalar field, renormalised where the window leaves the image.
std::vector<double> blur(const std::vector<double>& in, int width, int height) {
  const auto w = gaussian_weights();
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int xx = x + k;
        if (xx < 0 || xx >= width)
          continue;
        sum += w[size_t(k + kRadius)] * in[size_t(y) * size_t(width) + size_t(xx)];
        norm += w[size_t(k + kRadius)];
      }
      tmp[size_t(y) * size_t(width) + size_t(x)] = sum / norm;
    }
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      double sum = 0.0, norm = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int yy = y + k;
        if (yy < 0 || yy >= height)
          continue;
        sum += w[size_t(k + kRadius)] * tmp[size_t(yy) * size_t(width) + size_t(x)];
        norm += w[size_t(k + kRadius)];
      }
      out[size_t(y) * size_t(width) + size_t(x)] = sum / norm;
    }
  }
  return out;
}

bool counted(const PixelMask& mask, size_t i) {
  return mask.empty() || mask[i];
}

}  // namespace

PixelMask mask_from_image(const Image& image, float threshold) {
  PixelMask mask(image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec3 p = image.pixels[i];
    mask[i] = std::max({p.x, p.y, p.z}) > threshold;
  }
  return mask;
}

Image clamped_to_display(Image image) {
  for (glm::vec3& p : image.pixels)
    p = glm::clamp(p, glm::vec3(0.0f), glm::vec3(1.0f));
  return image;
}

bool is_display_image_file(const std::string& filename) {
  const std::string ext = lower_extension(filename);
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg";
}

Image display_encoded(Image image) {
  for (glm::vec3& p : image.pixels) {
    for (int c = 0; c < 3; ++c)
      p[c] = float(srgb_byte(p[c])) / 255.0f;
  }
  return image;
}

const char* metric_scale_name(MetricScale scale) {
  return scale == MetricScale::display ? "display (sRGB 8-bit)" : "linear light";
}

MetricScale match_metric_scale(Image& a, const std::string& a_file, Image& b,
                               const std::string& b_file, bool linear) {
  const bool display = is_display_image_file(a_file) || is_display_image_file(b_file);
  if (display && !linear) {
    a = display_encoded(std::move(a));
    b = display_encoded(std::move(b));
    return MetricScale::display;
  }
  if (display) {
    a = clamped_to_display(std::move(a));
    b = clamped_to_display(std::move(b));
  }
  return MetricScale::linear;
}

double psnr_from_mse(double mse, double peak) {
  if (mse <= 0.0)
    return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

std::vector<float> ssim_map(const Image& a, const Image& b, const MetricOptions& options) {
  const int width = a.width, height = a.height;
  const size_t n = a.pixels.size();
  const double c1 = (0.01 * options.peak) * (0.01 * options.peak);
  const double c2 = (0.03 * options.peak) * (0.03 * options.peak);
  std::vector<float> result(n, 0.0f);
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (int c = 0; c < 3; ++c) {
    for (size_t i = 0; i < n; ++i) {
      x[i] = a.pixels[i][c];
      y[i] = b.pixels[i][c];
      xx[i] = x[i] * x[i];
      yy[i] = y[i] * y[i];
      xy[i] = x[i] * y[i];
    }
    const auto mx = blur(x, width, height), my = blur(y, width, height);
    const auto sxx = blur(xx, width, height), syy = blur(yy, width, height),
               sxy = blur(xy, width, height);
    for (size_t i = 0; i < n; ++i) {
      const double vx = std::max(0.0, sxx[i] - mx[i] * mx[i]);
      const double vy = std::max(0.0, syy[i] - my[i] * my[i]);
      const double cov = sxy[i] - mx[i] * my[i];
      const double s = ((2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2)) /
                       ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
      result[i] += float(s / 3.0);
    }
  }
  return result;
}

ImageComparison compare_images(const Image& a, const Image& b, const PixelMask& mask,
                               const MetricOptions& options) {
  ImageComparison out;
  if (a.width != b.width || a.height != b.height || a.pixels.empty() ||
      (!mask.empty() && mask.size() != a.pixels.size())) {
    return out;
  }
  double sum_sq = 0.0, sum_abs = 0.0, max_abs = 0.0;
  bool not_a_number = false;  // a NaN difference: the largest error is NaN, not the others' max
  size_t count = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (!counted(mask, i))
      continue;
    ++count;
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.pixels[i][c]) - double(b.pixels[i][c]);
      sum_sq += d * d;
      sum_abs += std::abs(d);
      max_abs = std::max(max_abs, std::abs(d));
      not_a_number = not_a_number || std::isnan(d);
    }
  }
  if (count == 0)
    return out;
  const std::vector<float> ssim = ssim_map(a, b, options);
  double ssim_sum = 0.0;
  for (size_t i = 0; i < ssim.size(); ++i) {
    if (counted(mask, i))
      ssim_sum += ssim[i];
  }
  out.pixels = count;
  out.mse = sum_sq / double(3 * count);
  out.psnr = psnr_from_mse(out.mse, options.peak);
  out.ssim = ssim_sum / double(count);
  out.max_abs_error = not_a_number ? std::numeric_limits<double>::quiet_NaN() : max_abs;
  out.mean_abs_error = sum_abs / double(3 * count);
  return out;
}

Image error_heatmap(const Image& a, const Image& b, double scale, const PixelMask& mask) {
  Image out(a.width, a.height);
  if (a.width != b.width || a.height != b.height)
    return out;
  // Piecewise-linear ramp: black, blue, magenta, yellow, white.
  const std::array<glm::vec3, 5> ramp = {glm::vec3(0, 0, 0), glm::vec3(0, 0, 1), glm::vec3(1, 0, 1),
                                         glm::vec3(1, 1, 0), glm::vec3(1, 1, 1)};
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    if (!counted(mask, i)) {
      out.pixels[i] = glm::vec3(0.02f);
      continue;
    }
    const glm::vec3 d = glm::abs(a.pixels[i] - b.pixels[i]);
    const double e = std::max({d.x, d.y, d.z}) / std::max(scale, 1e-30);
    const double s = std::clamp(e, 0.0, 1.0) * double(ramp.size() - 1);
    const size_t k = std::min(size_t(s), ramp.size() - 2);
    out.pixels[i] = glm::mix(ramp[k], ramp[k + 1], float(s - double(k)));
  }
  return out;
}

}  // namespace gfield
