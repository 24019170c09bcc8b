#pragma once
// gfield-view's headless run of the glass method (runtime/methods/glass.hpp). Header-only:
// included by runtime/main.cpp.

#include <algorithm>
#include <cstdio>
#include <string>

#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/glass.hpp"

namespace gfield {

/// Renders `scene` by vertex displacement through its glass, writes `out` (if not empty) and,
/// with `bench`, prints the frame time averaged over all frames but the first. Returns the exit
/// code.
inline int run_glass_headless(const Scene& scene, const std::string& shader_dir,
                              const GlassSettings& settings, int width, int height,
                              const std::string& out, int frames, bool bench) {
  const auto fail = [](const std::string& message, int code) {
    std::fprintf(stderr, "gfield-view: %s\n", message.c_str());
    return code;
  };
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context)
    return fail(error, kExitNoOpenGL);
  GlassRenderer renderer;
  if (!renderer.load(scene, shader_dir, settings, error))
    return fail(error, 2);
  GlassStats first;
  Image image = renderer.render_image(width, height, settings, &first);
  GlassStats total;
  for (int f = 1; f < frames; ++f)
    image = renderer.render_image(width, height, settings, &total);
  if (!out.empty() && !save_image(out, image, error))
    return fail(error, 2);
  if (bench) {
    const int timed = frames > 1 ? frames - 1 : 1;
    const GlassStats& s = frames > 1 ? total : first;
    const double ms = s.milliseconds / timed;
    std::printf("renderer: %s (%s, %s)\n", context->renderer().c_str(), context->version().c_str(),
                context->platform().c_str());
    std::printf("glass: %dx%d, %lld opaque vertices, %d class images, %d spp\n", width, height,
                s.vertices, s.class_images, settings.samples_per_pixel);
    std::printf("first frame: %.2f ms (includes shader warm-up)\n", first.milliseconds);
    std::printf("frame: %.2f ms (%.1f FPS) over %d frames: peeling %.2f ms, class images %.2f ms\n",
                ms, 1000.0 / std::max(ms, 1e-6), timed, s.peel_milliseconds / timed,
                s.scene_milliseconds / timed);
  }
  return 0;
}

}  // namespace gfield
