// The Davis–Wyman paper's Table 1 on this machine's GL (llvmpipe here): frame time of
// `davis-wyman` with 1-4 internal bounces (and 3 with back faces only for later bounces) beside
// `wyman2005`, `cubemap` and the geometry-field refraction (the `field` method, refined mode), on
// the refractive-mesh scene data/scenes/davis-wyman-color-chart.json, at 512^2 and 1024^2; the
// reference tracer's wall time for the same image in the same run (`gfield render --spp 1
// --dielectric tir-only`, the paper's Figure 8 reference) and each method's ratio to it; the PSNR
// of each method's whole picture (values clamped to [0, 1]) against that reference and against
// the full-Fresnel one (`--dielectric full`, what the geometry-field renderer computes).
// A second table: `envmap` (the classic environment-mapped reflection) against the geometry field
// on the mirror scenes at 256^2, against `gfield render --spp 1`.
// Mesh assets are built with `gfield build` (its defaults, as scripts/demo.sh) and `gfield
// thickness` into a temporary folder. Frame times: wall and GPU, median and range of F frames
// (default 10 up to 512^2, 3 above) after warm-up frames until two agree
// (runtime/frame_timing.hpp).
//
// Usage: bench_image_space_refraction [--frames F] [SIZE...]   (default 512 1024)

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "example_scenes.hpp"
#include "gfield/image_metrics.hpp"
#include "gl_bench_setup.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/frame_timing.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/cube_map.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/methods/image_space_refraction.hpp"
#include "runtime/shader_program.hpp"
#include "runtime_runs.hpp"
#include "time_text.hpp"

namespace fs = std::filesystem;
using namespace gfield;

namespace {

constexpr int kDepth = 10;  // `gfield render`'s default and GeometryFieldSettings' default

/// The reference tracer's picture (1 spp at the pixel centres, clamped) and its time in ms.
Image reference_image(const ReferenceTracer& tracer, int size, DielectricMode mode, double& ms) {
  RenderOptions options;
  options.width = options.height = size;
  options.samples_per_pixel = 1;
  options.max_depth = kDepth;
  options.dielectric = mode;
  options.jitter = false;
  RenderStats stats;
  Image image = clamped_to_display(tracer.render(options, &stats));
  ms = stats.seconds * 1e3;
  return image;
}

/// A frame of a GL method: its picture, its parts and counts added to the stats given (if any).
using FrameFunction = std::function<Image(FrameStats* stats)>;

/// A frame of `method` at size^2, 1 sample per pixel, `configure` applied first.
FrameFunction method_frame(Method& method, const Camera& camera, int size,
                           std::function<void()> configure = {}) {
  return [&method, &camera, size, configure](FrameStats* stats) {
    if (configure)
      configure();
    return render_image(method, camera, size, size, 1, stats);
  };
}

struct Row {
  std::string method;
  TimeSummary wall, gpu;  ///< per timed frame, ms
  Image image;            ///< the last frame, clamped
};

/// Warm-up frames until two agree (shader compilation, buffer allocation), then `frames` timed.
Row timed_row(const std::string& method, int frames, const FrameFunction& frame) {
  Row row;
  row.method = method;
  const FrameTimes times =
      time_frames([&](FrameStats* stats) { row.image = frame(stats); }, frames);
  row.wall = summarize(times.wall_ms);
  row.gpu = summarize(times.gpu_ms);
  row.image = clamped_to_display(std::move(row.image));
  return row;
}

/// The example scene `name` (with thickness maps when `thickness_maps`: wyman2005 needs them)
/// and the reference tracer on it.
bool load_scene_and_tracer(const std::string& name, const fs::path& dir, bool thickness_maps,
                           Scene& scene, ReferenceTracer& tracer) {
  std::string file, error;
  if (!prepare_example_scene(name, dir, thickness_maps, file) ||
      !load_scene(file, scene, error, OutsidePaths::kAllowed) || !tracer.build(scene, error)) {
    std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
    return false;
  }
  return true;
}

/// Table 1: the refractive-mesh scene at each size.
void refraction_table(const fs::path& dir, const std::vector<int>& sizes, int frames_per_row) {
  Scene scene;
  ReferenceTracer tracer;
  if (!load_scene_and_tracer("davis-wyman-color-chart", dir, true, scene, tracer))
    return;
  std::string error;
  GpuScene gpu;
  ImageSpaceRefractionMethod davis_wyman(true), wyman2005(false);
  CubeMapMethod cubemap(false);
  GeometryFieldMethod field;
  if (!gpu.load(scene, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return;
  }
  for (Method* method : std::vector<Method*>{&davis_wyman, &wyman2005, &cubemap, &field}) {
    if (!method->load(gpu, default_shader_dir(), error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return;
    }
  }
  ImageSpaceRefractionSettings& dw = davis_wyman.settings();
  const Camera& camera = scene.camera;
  for (int size : sizes) {
    const int frames = frames_per_row > 0 ? frames_per_row : size <= 512 ? 10 : 3;
    double tir_ms = 0.0, full_ms = 0.0;
    const Image tir_only = reference_image(tracer, size, DielectricMode::kTirOnly, tir_ms);
    const Image full = reference_image(tracer, size, DielectricMode::kFull, full_ms);
    std::vector<Row> rows;
    for (int bounces = 1; bounces <= 4; ++bounces) {
      rows.push_back(timed_row(
          "davis-wyman, " + std::to_string(bounces) + " bounce" + (bounces > 1 ? "s" : ""), frames,
          method_frame(davis_wyman, camera, size, [&dw, bounces] {
            dw.bounces = bounces;
            dw.back_only_later = false;
          })));
    }
    rows.push_back(timed_row("davis-wyman, 3 bounces, --back-only-later", frames,
                             method_frame(davis_wyman, camera, size, [&dw] {
                               dw.bounces = 3;
                               dw.back_only_later = true;
                             })));
    rows.push_back(timed_row("wyman2005", frames, method_frame(wyman2005, camera, size)));
    rows.push_back(timed_row("cubemap (per fragment, 256^2 faces)", frames,
                             method_frame(cubemap, camera, size)));
    settle_pass_trial(field, camera, size);
    rows.push_back(timed_row("geometry field (refined, depth 10), " + field.pass_status(), frames,
                             method_frame(field, camera, size)));

    std::printf("\ndavis-wyman-color-chart %dx%d, %d timed frames:\n\n", size, size, frames);
    std::printf(
        "| method | ms/frame (min-max) | GPU ms (min-max) | / reference | PSNR vs tir-only | PSNR "
        "vs full |\n");
    std::printf("|---|---:|---:|---:|---:|---:|\n");
    for (const Row& row : rows)
      std::printf("| %s | %s | %s | %.3f | %.2f dB | %.2f dB |\n", row.method.c_str(),
                  range_text(row.wall).c_str(), range_text(row.gpu).c_str(),
                  row.wall.median / tir_ms, compare_images(row.image, tir_only).psnr,
                  compare_images(row.image, full).psnr);
    std::printf("| reference tracer, tir-only, 1 spp | %.1f | | 1 | | %.2f dB |\n", tir_ms,
                compare_images(tir_only, full).psnr);
    std::printf("| reference tracer, full Fresnel, 1 spp | %.1f | | %.3f | %.2f dB | |\n", full_ms,
                full_ms / tir_ms, compare_images(full, tir_only).psnr);
    std::printf("\n%s\n", kFrameTimeNote);
    std::fflush(stdout);
  }
}

/// envmap against the geometry field on the mirror scenes.
void envmap_table(const fs::path& dir, int size, int frames) {
  std::printf(
      "\nmirror scenes %dx%d, %d timed frames, reference `gfield render --spp 1 --depth %d`:\n\n",
      size, size, frames, kDepth);
  std::printf("| scene | method | ms/frame (min-max) | GPU ms (min-max) | / reference | PSNR |\n");
  std::printf("|---|---|---:|---:|---:|---:|\n");
  for (const char* name : {"mirror-torus-instances", "two-mirror-spheres"}) {
    Scene scene;
    ReferenceTracer tracer;
    if (!load_scene_and_tracer(name, dir, false, scene, tracer))
      continue;
    std::string error;
    GpuScene gpu;
    CubeMapMethod envmap(true);
    GeometryFieldMethod field;
    if (!gpu.load(scene, error) || !envmap.load(gpu, default_shader_dir(), error) ||
        !field.load(gpu, default_shader_dir(), error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      continue;
    }
    double reference_ms = 0.0;
    const Image reference = reference_image(tracer, size, DielectricMode::kFull, reference_ms);
    settle_pass_trial(field, scene.camera, size);
    const Row rows[] = {
        timed_row("envmap (256^2 faces)", frames, method_frame(envmap, scene.camera, size)),
        timed_row("geometry field (refined), " + field.pass_status(), frames,
                  method_frame(field, scene.camera, size))};
    for (const Row& row : rows)
      std::printf("| %s | %s | %s | %s | %.3f | %.2f dB |\n", name, row.method.c_str(),
                  range_text(row.wall).c_str(), range_text(row.gpu).c_str(),
                  row.wall.median / reference_ms, compare_images(row.image, reference).psnr);
    std::printf("| %s | reference tracer, 1 spp | %.1f | | 1 | |\n", name, reference_ms);
    std::fflush(stdout);
  }
  std::printf("\n%s\n", kFrameTimeNote);
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows reach a file as they are measured
  GlBenchArguments arguments;
  if (!parse_gl_bench_arguments(argc, argv, "bench_image_space_refraction", arguments))
    return 2;
  const BenchFolder folder("gfield_bench_image_space_refraction");
  const fs::path& dir = folder.path;
  auto context = create_bench_context();
  if (!context)
    return kExitNoOpenGL;
  refraction_table(dir, arguments.sizes, arguments.frames);
  envmap_table(dir, 256, arguments.frames > 0 ? arguments.frames : 10);
  return 0;
}
