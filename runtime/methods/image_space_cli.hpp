#pragma once
// gfield-view's options and headless run for the image-space methods (cubemap, envmap,
// wyman2005, davis-wyman), plus the comparisons any method can use: a side-by-side picture of two
// methods and the difference against a reference render (PSNR, SSIM, an error heat map).
// Header-only: included by runtime/main.cpp, which links CLI11.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gfield/image.hpp"
#include "gfield/image_metrics.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/image_space.hpp"
#include "runtime/renderer.hpp"

namespace gfield {

/// The method names gfield-view accepts for the image-space renderer.
inline const std::vector<std::string>& image_space_method_names() {
  static const std::vector<std::string> names = {"cubemap", "envmap", "wyman2005", "davis-wyman"};
  return names;
}

struct ImageSpaceOptions {
  ImageSpaceSettings settings;
  std::string background = "depth-map";
  std::string side_by_side;  ///< a second method drawn to the right ("field" or image-space)
  std::string reference;     ///< a reference picture (.exr) to compare with
  std::string difference;    ///< where to write the error heat map against `reference`
  float difference_scale = 0.25f;
};

inline void add_image_space_options(CLI::App& app, const std::shared_ptr<ImageSpaceOptions>& o) {
  ImageSpaceSettings& s = o->settings;
  const char* group = "Image-space methods (cubemap, envmap, wyman2005, davis-wyman)";
  app.add_option("--bounces", s.bounces, "davis-wyman: internal bounces (0-4 in the paper)")
      ->check(CLI::Range(0, 16))
      ->group(group);
  app.add_option("--iterations-first", s.iterations_first,
                 "davis-wyman: binary-search steps on the first transmitted ray")
      ->check(CLI::Range(0, 32))
      ->group(group);
  app.add_option("--iterations-later", s.iterations_later,
                 "davis-wyman: binary-search steps on later rays")
      ->check(CLI::Range(0, 32))
      ->group(group);
  app.add_option("--exit-iterations", s.exit_iterations,
                 "binary-search steps in the nearby-geometry map")
      ->check(CLI::Range(0, 32))
      ->group(group);
  app.add_flag("--back-only-later", s.back_only_later,
               "davis-wyman: later bounces search the back faces only (the paper's speed-up)")
      ->group(group);
  app.add_option("--buffer-scale", s.buffer_scale,
                 "side of the intermediate buffers as a fraction of the picture's")
      ->check(CLI::Range(0.0625, 1.0))
      ->group(group);
  app.add_option("--background", o->background,
                 "where leaving rays look: depth-map (nearby geometry) or analytic shapes")
      ->check(CLI::IsMember({"depth-map", "analytic"}))
      ->group(group);
  app.add_option("--min-alignment", s.min_alignment,
                 "cosine below which a depth-map candidate counts as a miss")
      ->check(CLI::Range(-1.0, 1.0))
      ->group(group);
  app.add_option("--cube-size", s.cube_size, "cubemap/envmap: texels per cube face")
      ->check(CLI::Range(8, 4096))
      ->group(group);
  app.add_flag("--per-vertex", s.per_vertex,
               "cubemap: Hurley's per-vertex refraction vector (default: Snell per fragment)")
      ->group(group);
  app.add_flag("--fresnel", s.fresnel, "cubemap: blend in the Fresnel reflection")->group(group);
  app.add_option("--side-by-side", o->side_by_side,
                 "headless: draw this second method to the right of the first")
      ->group(group);
  app.add_option("--reference", o->reference,
                 "headless: compare with this picture (.exr), print PSNR and SSIM")
      ->check(CLI::ExistingFile)
      ->group(group);
  app.add_option("--diff", o->difference,
                 "headless: write the error heat map against --reference here (.png/.exr)")
      ->group(group);
  app.add_option("--diff-scale", o->difference_scale, "error shown white in the heat map")
      ->group(group);
}

/// Renders `method` ("field" or an image-space name) once at width x height.
inline bool render_any_method(const Scene& scene, const std::string& shader_dir,
                              const std::string& method, const ImageSpaceOptions& options,
                              const RenderSettings& field_settings, int width, int height,
                              int frames, Image& image, double& milliseconds, std::string& error) {
  milliseconds = 0.0;
  if (method == "field") {
    Renderer renderer;
    if (!renderer.load(scene, shader_dir, error))
      return false;
    FrameStats first, total;
    image = renderer.render_image(width, height, field_settings, &first);
    for (int f = 1; f < frames; ++f)
      image = renderer.render_image(width, height, field_settings, &total);
    milliseconds = frames > 1 ? total.milliseconds / (frames - 1) : first.milliseconds;
    return true;
  }
  ImageSpaceSettings settings = options.settings;
  if (!parse_image_space_method(method, settings.method)) {
    error = "unknown method " + method;
    return false;
  }
  settings.background =
      options.background == "analytic" ? ExitBackground::kAnalytic : ExitBackground::kDepthMap;
  ImageSpaceRenderer renderer;
  if (!renderer.load(scene, shader_dir, error) || !renderer.supports(settings.method, error))
    return false;
  ImageSpaceStats first, total;
  image = renderer.render_image(width, height, settings, &first);
  for (int f = 1; f < frames; ++f)
    image = renderer.render_image(width, height, settings, &total);
  milliseconds = frames > 1 ? total.milliseconds / (frames - 1) : first.milliseconds;
  return true;
}

/// gfield-view --headless for an image-space method (or any method with --side-by-side /
/// --reference). Returns the exit code.
inline int run_image_space_headless(const Scene& scene, const std::string& shader_dir,
                                    const std::string& method, const ImageSpaceOptions& options,
                                    const RenderSettings& field_settings, int width, int height,
                                    const std::string& out, int frames, bool bench) {
  const auto fail = [](const std::string& message, int code) {
    std::fprintf(stderr, "gfield-view: %s\n", message.c_str());
    return code;
  };
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context)
    return fail(error, kExitNoOpenGL);
  Image image;
  double ms = 0.0;
  if (!render_any_method(scene, shader_dir, method, options, field_settings, width, height, frames,
                         image, ms, error))
    return fail(error, 2);
  if (bench) {
    std::printf("renderer: %s (%s, %s)\n", context->renderer().c_str(), context->version().c_str(),
                context->platform().c_str());
    std::printf("%s: %dx%d, %.2f ms per frame (%.1f FPS) over %d frame(s)\n", method.c_str(), width,
                height, ms, 1000.0 / std::max(ms, 1e-6), frames > 1 ? frames - 1 : 1);
  }
  if (!options.reference.empty()) {
    Image reference;
    if (!load_image(options.reference, reference, error))
      return fail(error, 2);
    if (reference.width != width || reference.height != height)
      return fail(options.reference + ": " + std::to_string(reference.width) + "x" +
                      std::to_string(reference.height) + ", the render is " +
                      std::to_string(width) + "x" + std::to_string(height),
                  2);
    const ImageComparison c = compare_images(image, reference);
    std::printf("%s vs %s: PSNR %.2f dB, SSIM %.4f, mean |error| %.4f\n", method.c_str(),
                options.reference.c_str(), c.psnr, c.ssim, c.mean_abs_error);
    if (!options.difference.empty() &&
        !save_image(options.difference, error_heatmap(image, reference, options.difference_scale),
                    error))
      return fail(error, 2);
  }
  if (!options.side_by_side.empty()) {
    Image second;
    double second_ms = 0.0;
    if (!render_any_method(scene, shader_dir, options.side_by_side, options, field_settings, width,
                           height, frames, second, second_ms, error))
      return fail(error, 2);
    if (bench)
      std::printf("%s: %dx%d, %.2f ms per frame\n", options.side_by_side.c_str(), width, height,
                  second_ms);
    Image both(2 * width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        both.at(x, y) = image.at(x, y);
        both.at(width + x, y) = second.at(x, y);
      }
    image = std::move(both);
  }
  if (!out.empty() && !save_image(out, image, error))
    return fail(error, 2);
  return 0;
}

}  // namespace gfield
