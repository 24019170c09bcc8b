// gfield compare A B [--heatmap OUT.png] [--mask M] [--json]: PSNR and SSIM of two images.

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "preprocess/cli/commands.hpp"

namespace gfield {
namespace {

struct CompareArgs {
  std::string a, b, heatmap, mask;
  double heatmap_scale = 0.0;
  bool json = false;
  bool linear = false;
};

Image load_or_throw(const std::string& file) {
  Image image;
  std::string error;
  if (!load_image(file, image, error))
    throw CommandError(error);
  return image;
}

void run_compare(const CompareArgs& args) {
  Image a = load_or_throw(args.a);
  Image b = load_or_throw(args.b);
  if (a.width != b.width || a.height != b.height) {
    throw CommandError(args.b + ": size " + std::to_string(b.width) + "x" +
                       std::to_string(b.height) + " differs from " + args.a + " (" +
                       std::to_string(a.width) + "x" + std::to_string(a.height) + ")");
  }
  PixelMask mask;
  if (!args.mask.empty()) {
    const Image m = load_or_throw(args.mask);
    if (m.width != a.width || m.height != a.height) {
      throw CommandError(args.mask + ": mask size differs from the images");
    }
    mask = mask_from_image(m);
  }
  const MetricScale scale = match_metric_scale(a, args.a, b, args.b, args.linear);
  const ImageComparison c = compare_images(a, b, mask);
  if (c.pixels == 0)
    throw CommandError(args.mask + ": the mask selects no pixel");
  if (!args.heatmap.empty()) {
    const double scale =
        args.heatmap_scale > 0.0 ? args.heatmap_scale : std::max(c.max_abs_error, 1e-6);
    std::string error;
    if (!save_image(args.heatmap, error_heatmap(a, b, scale, mask), error)) {
      throw CommandError(error);
    }
  }
  if (args.json) {
    nlohmann::json j;
    j["a"] = args.a;
    j["b"] = args.b;
    j["pixels"] = c.pixels;
    j["psnr_db"] = std::isinf(c.psnr) ? nlohmann::json("inf") : nlohmann::json(c.psnr);
    j["ssim"] = c.ssim;
    j["mse"] = c.mse;
    j["max_abs_error"] = c.max_abs_error;
    j["mean_abs_error"] = c.mean_abs_error;
    if (!args.mask.empty())
      j["mask"] = args.mask;
    j["scale"] = metric_scale_name(scale);
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("scale           %s\n", metric_scale_name(scale));
    std::printf("pixels          %zu\n", c.pixels);
    std::printf("PSNR            %.3f dB\n", c.psnr);
    std::printf("SSIM            %.5f\n", c.ssim);
    std::printf("MSE             %.6g\n", c.mse);
    std::printf("max |a-b|       %.6g\n", c.max_abs_error);
    std::printf("mean |a-b|      %.6g\n", c.mean_abs_error);
  }
}

}  // namespace

void add_compare_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "compare",
      "Compare two images (EXR, HDR, PNG, JPEG): PSNR, SSIM, errors (peak 1).\n"
      "PSNR = 10 log10(1 / MSE) over the 3 channels; SSIM with an 11x11 Gaussian window.\n"
      "Where either is a display picture (PNG, JPEG), both are compared on the values a PNG\n"
      "stores (sRGB, 8 bits, as ImageMagick and scikit-image do); two EXR/HDR pictures, or\n"
      "--linear, in linear light.");
  auto args = std::make_shared<CompareArgs>();
  cmd->add_option("A", args->a, "first image")->required();
  cmd->add_option("B", args->b, "second image (e.g. the reference)")->required();
  cmd->add_option("--heatmap", args->heatmap, "write a false-colour map of |A-B| (PNG or EXR)");
  cmd->add_option("--heatmap-scale", args->heatmap_scale,
                  "error shown as white (default: the largest error)");
  cmd->add_option("--mask", args->mask, "count only pixels where this image is > 0.5");
  cmd->add_flag("--json", args->json, "print the result as JSON");
  cmd->add_flag("--linear", args->linear,
                "compare in linear light (display pictures decoded and clamped to [0, 1])");
  cmd->callback([args] { run_compare(*args); });
}

}  // namespace gfield
