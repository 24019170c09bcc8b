// gfield-view's geometry-field renderer on this machine's GL (llvmpipe here): ms per frame per
// lookup mode at 512^2 and 1024^2, ns per traced pixel per bounce, the reference tracer's time
// for the same image (1 spp, same depth) in the same run, and the PSNR of the refined render
// against it. Example scenes of data/scenes, their mesh assets built with `gfield build` (its
// defaults, as scripts/demo.sh) into a temporary folder.
//
// Usage: bench_runtime_field [--frames F] [SIZE...]   (default 512 1024, 2 frames)

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "example_scenes.hpp"
#include "gfield/image_metrics.hpp"
#include "gl_bench_setup.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/shader_program.hpp"

namespace fs = std::filesystem;
using namespace gfield;

int main(int argc, char** argv) {
  GlBenchArguments arguments;
  if (!parse_gl_bench_arguments(argc, argv, "bench_runtime_field", arguments))
    return 2;
  const int frames = arguments.frames > 0 ? arguments.frames : 2;
  const fs::path dir = fs::temp_directory_path() / "gfield_bench_runtime_field";
  fs::create_directories(dir);
  auto context = create_bench_context();
  if (!context)
    return kExitNoOpenGL;
  std::string error;
  constexpr int kDepth = 4;
  for (const char* name :
       {"mirror-torus-instances", "two-mirror-spheres", "davis-wyman-color-chart"}) {
    std::string file;
    Scene scene;
    if (!prepare_example_scene(name, dir, false, file) ||
        !load_scene(file, scene, error, OutsidePaths::kAllowed)) {
      std::fprintf(stderr, "%s: %s\n", name, error.c_str());
      continue;
    }
    GpuScene gpu;
    GeometryFieldMethod field;
    if (!gpu.load(scene, error) || !field.load(gpu, default_shader_dir(), error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      continue;
    }
    ReferenceTracer tracer;
    if (!tracer.build(scene, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      continue;
    }
    for (int size : arguments.sizes) {
      RenderOptions options;
      options.width = options.height = size;
      options.samples_per_pixel = 1;
      options.max_depth = kDepth;
      options.jitter = false;
      RenderStats reference_stats;
      const Image reference = clamped_to_display(tracer.render(options, &reference_stats));
      std::printf("%s %dx%d depth %d: reference tracer %.1f ms (1 spp, %u cores)\n", name, size,
                  size, kDepth, reference_stats.seconds * 1e3, std::thread::hardware_concurrency());
      for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
        field.settings().mode = mode;
        field.settings().max_depth = kDepth;
        render_image(field, scene.camera, size, size, 1);  // warm-up (shader compilation)
        FrameStats stats;
        Image image;
        for (int f = 0; f < frames; ++f)
          image = render_image(field, scene.camera, size, size, 1, &stats);
        const double ms = stats.milliseconds / frames;
        const double rays = stats.count("secondary rays") / frames;
        const double psnr = compare_images(clamped_to_display(image), reference).psnr;
        std::printf(
            "  %-8s %8.1f ms/frame (%.2fx the reference tracer), %.1f ns per traced pixel "
            "per bounce, %.0f traced pixels, PSNR %.2f dB\n",
            lookup_mode_name(mode), ms, ms / (reference_stats.seconds * 1e3),
            rays > 0 ? stats.part_ms("tracing") / frames * 1e6 / rays : 0.0,
            stats.count("traced pixels") / frames, psnr);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
