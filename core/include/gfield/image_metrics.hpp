#pragma once
// Image comparison: PSNR and SSIM of two linear RGB images, optionally restricted to a mask
// (e.g. the pixels an object covers).

#include <string>
#include <vector>

#include "gfield/image.hpp"

namespace gfield {

/// Which pixels count: empty = all; otherwise width * height flags (row-major, top row first).
using PixelMask = std::vector<bool>;

/// A mask from an image: pixels whose largest channel exceeds `threshold` are in.
PixelMask mask_from_image(const Image& image, float threshold = 0.5f);

/// The picture as displayed: every channel clamped to [0, 1]. Comparisons of renders use it
/// (the studio environment's softboxes reach 6; unclamped, a few reflections of them would
/// dominate every PSNR).
Image clamped_to_display(Image image);

/// Whether `filename` holds a display picture (PNG, JPEG: 8-bit, clamped to [0, 1] when written)
/// rather than radiance (EXR, HDR).
bool is_display_image_file(const std::string& filename);

/// Gives two pictures read from `a_file` and `b_file` the same display transform before they are
/// compared: where either is a display picture, both are clamped to [0, 1] (a radiance picture
/// against a clamped one would count every highlight above 1 as error); two radiance pictures
/// stay linear. Returns whether they were clamped.
bool match_display_transform(Image& a, const std::string& a_file, Image& b,
                             const std::string& b_file);

struct ImageComparison {
  double mse = 0.0;             ///< mean over counted pixels and the 3 channels of (a - b)^2
  double psnr = 0.0;            ///< 10 log10(peak^2 / mse) in dB; +infinity when mse == 0
  double ssim = 0.0;            ///< mean SSIM over counted pixels (mean of the 3 channels)
  double max_abs_error = 0.0;   ///< largest |a - b| of any channel of a counted pixel
  double mean_abs_error = 0.0;  ///< mean |a - b| over counted pixels and channels
  size_t pixels = 0;            ///< counted pixels
};

/// Peak signal value for PSNR and the dynamic range L of SSIM (1 for images in [0,1]).
struct MetricOptions {
  double peak = 1.0;
};

/// PSNR in dB from a mean squared error: 10 log10(peak^2 / mse); +infinity for mse == 0.
double psnr_from_mse(double mse, double peak = 1.0);

/// Per-pixel SSIM (Wang et al. 2004): 11 x 11 Gaussian window (sigma 1.5, truncated and
/// renormalised at the image border), K1 = 0.01, K2 = 0.03, L = peak, per channel then averaged.
/// Returns width * height values. Images must have the same size.
std::vector<float> ssim_map(const Image& a, const Image& b, const MetricOptions& options = {});

/// Compares `a` with `b` (same size required; an empty comparison has pixels == 0) over the
/// pixels of `mask` (empty: all pixels).
ImageComparison compare_images(const Image& a, const Image& b, const PixelMask& mask = {},
                               const MetricOptions& options = {});

/// A false-colour map of |a - b| (max over channels) for looking at: black (0) through blue,
/// magenta and yellow to white (>= `scale`). Masked-out pixels are dark grey.
Image error_heatmap(const Image& a, const Image& b, double scale, const PixelMask& mask = {});

}  // namespace gfield
