#pragma once
// Image comparison: PSNR and SSIM of two RGB images, optionally restricted to a mask (e.g. the
// pixels an object covers), on one of two scales: the values a display picture stores (as
// ImageMagick, scikit-image and OpenCV compare PNGs) or linear light.

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

/// The picture as a PNG stores it: every channel clamped to [0, 1], sRGB-encoded and rounded to
/// k / 255. A PNG read by load_image comes back to its stored values exactly.
Image display_encoded(Image image);

/// The values two pictures are compared on.
enum class MetricScale {
  display,  ///< display_encoded values: the scale of ImageMagick's and scikit-image's PSNR
  linear,   ///< linear light, clamped to [0, 1] where either picture is a display picture
};

/// How `scale` is named in the tools' output: "display (sRGB 8-bit)" or "linear light".
const char* metric_scale_name(MetricScale scale);

/// Puts two pictures read from `a_file` and `b_file` ("" for one that is not a file) on one
/// scale before they are compared, and returns it: where either is a display picture (PNG,
/// JPEG) and `linear` is not asked, both become display_encoded; otherwise linear light, both
/// clamped to [0, 1] where either is a display picture (a radiance picture against a clamped
/// one would count every highlight above 1 as error); two radiance pictures stay as they are.
MetricScale match_metric_scale(Image& a, const std::string& a_file, Image& b,
                               const std::string& b_file, bool linear = false);

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
