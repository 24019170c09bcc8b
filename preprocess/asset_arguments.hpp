#pragma once
// The asset pipeline's knobs as a user gives them (`gfield build` and `gfield batch` options,
// gfield.build's keyword arguments in Python), their checks (one wording for both), and the
// AssetOptions they make.

#include <cmath>
#include <exception>
#include <string>

#include "preprocess/asset_build.hpp"

namespace gfield {

struct AssetArguments {
  std::string size = "auto";
  double max_image_error = kDefaultMaxMeanError;
  size_t proxy_above = kDefaultProxyAbove;  ///< GeometryImageOptions::proxy_above
  int samples = 24;
  int format = kFieldFormatVersion;  ///< 3, or 2 (layered, with `layers`)
  int layers = kAutoLayers;
  bool half = false;  ///< the default; the flag exists for symmetry with --float
  bool full = false;
  size_t verify_rays = kDefaultVerifyRays;
  std::string method = "auto";
  std::string components = "all";
  bool allow_outside_paths = false;
};

/// The image size of --size: "auto" (kAutoImageSize) or texels per side. False for other words.
inline bool image_size_from_text(const std::string& text, int& size) {
  if (text == "auto") {
    size = kAutoImageSize;
    return true;
  }
  size_t end = 0;
  try {
    size = std::stoi(text, &end);
  } catch (const std::exception&) {
    return false;
  }
  return end == text.size() && size >= kMinImageSize && size <= kMaxImageSize;
}

/// What is wrong with an image size given as `text` ("" when it is auto or a size in range).
inline std::string image_size_problem(const std::string& text) {
  int size = 0;
  return image_size_from_text(text, size)
             ? std::string()
             : "expected auto or texels per side in [" + std::to_string(kMinImageSize) + ", " +
                   std::to_string(kMaxImageSize) + "], got " + text;
}

/// What is wrong with a --max-image-error of `value`, given as `text` ("" when it is a finite
/// positive percentage).
inline std::string max_image_error_problem(double value, const std::string& text) {
  return std::isfinite(value) && value > 0.0 ? std::string()
                                             : "expected a positive percentage, got " + text;
}

inline AssetOptions asset_options(const AssetArguments& args) {
  AssetOptions options;
  image_size_from_text(args.size, options.image.size);  // checked by image_size_problem
  options.image.max_mean_error = args.max_image_error;
  options.image.proxy_above = args.proxy_above;
  options.image.method = args.method == "orbifold" ? ParameterizationMethod::kOrbifold
                         : args.method == "square" ? ParameterizationMethod::kSquare
                                                   : ParameterizationMethod::kAuto;
  options.image.components =
      args.components == "largest" ? ComponentSelection::kLargest : ComponentSelection::kAll;
  options.samples_per_side = args.samples;
  options.field.version = args.format;
  options.field.layers = args.layers;
  options.field.precision = args.full ? ExrPrecision::kFloat : ExrPrecision::kHalf;
  options.verify_rays = args.verify_rays;
  options.outside_paths =
      args.allow_outside_paths ? OutsidePaths::kAllowed : OutsidePaths::kRefused;
  return options;
}

}  // namespace gfield
