// gfield-view's geometry-field method against its peer and its floor, on this machine's GL
// (llvmpipe on the CI machine): per example scene, picture size and depth, ms per frame with
// the meshes looked up in their geometry fields (refined; at depth 4 also nearest and linear)
// and traced exactly through BVHs of their triangles (--intersect bvh), each against the Embree
// reference tracer's time for the same picture (1 spp, same depth) in the same run, the PSNR of
// each against that reference, the GPU bytes of each (geometry image + field against BVH + the
// rasterised mesh, which both draw), secondary rays per traced pixel, and the work each does
// (field texel and image texel fetches and Newton steps per lookup, nodes and triangles per BVH
// traversal: counted on the GPU, independent of the device). Prints markdown tables. Assets are
// built with `gfield build` (its defaults, as scripts/demo.sh) into a temporary folder.
//
// Usage: bench_runtime_field [--frames F] [--depths D,D,...] [SIZE...]
//        (default: 2 frames, depths 1,2,4, sizes 512 1024)

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "example_scenes.hpp"
#include "gfield/image_metrics.hpp"
#include "gfield/stopwatch.hpp"
#include "gl_bench_setup.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "runtime/shader_program.hpp"
#include "runtime_runs.hpp"

namespace fs = std::filesystem;
using namespace gfield;

namespace {

/// The reference tracer's time for the same picture: wall and CPU (all threads) ms.
struct ReferenceTime {
  double ms = 0.0;
  double cpu_ms = 0.0;
};

void print_row(const char* what, const Run& r, const ReferenceTime& reference,
               const FrameStats& rays) {
  const double traced = rays.count("traced pixels");
  std::printf("| %s | %s | %.2f | %.2f | %.2f | %.2f | %s |\n", what, ms_text(r).c_str(),
              r.ms / reference.ms, r.cpu_ms / reference.cpu_ms, r.psnr,
              traced > 0.0 ? rays.count("secondary rays") / traced : 0.0,
              work_line(r.per_sample).c_str());
}

/// The rows of one scene, size and depth.
void bench_depth(GeometryFieldMethod& method, ReferenceTracer& tracer, const Scene& scene, int size,
                 int depth, int frames) {
  RenderOptions options;
  options.width = options.height = size;
  options.samples_per_pixel = 1;
  options.max_depth = depth;
  options.jitter = false;
  RenderStats reference_stats;
  const double cpu_start = process_cpu_ms();
  const Image reference = clamped_to_display(tracer.render(options, &reference_stats));
  ReferenceTime reference_time;
  reference_time.cpu_ms = process_cpu_ms() - cpu_start;
  reference_time.ms = reference_stats.seconds * 1e3;
  std::printf("\n%dx%d, depth %d; reference tracer %.1f ms, CPU %.1f ms (1 spp, %u cores)\n\n",
              size, size, depth, reference_time.ms, reference_time.cpu_ms,
              std::thread::hardware_concurrency());
  std::printf(
      "| intersection | ms/frame | x reference | x reference (CPU time) | PSNR dB | rays / "
      "traced pixel | work |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  method.settings().max_depth = depth;
  method.settings().intersect = MeshIntersection::kField;
  Run field;
  for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
    if (mode != LookupMode::kRefined && depth != 4)
      continue;
    method.settings().mode = mode;
    field = run(method, scene, size, frames, reference);
    print_row((std::string("field, ") + lookup_mode_name(mode)).c_str(), field, reference_time,
              field.per_sample);
  }
  method.settings().intersect = MeshIntersection::kBvh;
  const Run bvh = run(method, scene, size, frames, reference);
  print_row("bvh (exact)", bvh, reference_time, bvh.per_sample);
  method.settings().intersect = MeshIntersection::kField;
  std::printf("\nfield (refined) / bvh time: %.2f\n%s\n", field.ms / bvh.ms, kFrameTimeNote);
  std::fflush(stdout);
}

bool parse_depths(const char* text, std::vector<int>& depths) {
  depths.clear();
  for (const char* p = text; *p != '\0';) {
    char* end = nullptr;
    const long d = std::strtol(p, &end, 10);
    if (end == p || d < 0 || d > 64 || (*end != ',' && *end != '\0'))
      return false;
    depths.push_back(int(d));
    p = *end == ',' ? end + 1 : end;
  }
  return !depths.empty();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> depths = {1, 2, 4};
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--depths" && i + 1 < argc) {
      if (!parse_depths(argv[++i], depths)) {
        std::fprintf(stderr, "--depths %s: expected D,D,... in [0, 64]\n", argv[i]);
        return 2;
      }
    } else {
      rest.push_back(argv[i]);
    }
  }
  GlBenchArguments arguments;
  if (!parse_gl_bench_arguments(int(rest.size()), rest.data(), "bench_runtime_field", arguments))
    return 2;
  const int frames = arguments.frames > 0 ? arguments.frames : 2;
  const BenchFolder folder("gfield_bench_runtime_field");
  const fs::path& dir = folder.path;
  auto context = create_bench_context();
  if (!context)
    return kExitNoOpenGL;
  std::string error;
  for (const char* name : {"mirror-torus-instances", "textured-mirror", "davis-wyman-color-chart",
                           "two-mirror-spheres"}) {
    std::string file;
    Scene scene;
    GpuScene gpu;
    GeometryFieldMethod method;
    ReferenceTracer tracer;
    if (!prepare_example_scene(name, dir, false, file) ||
        !load_scene(file, scene, error, OutsidePaths::kAllowed) || !gpu.load(scene, error) ||
        !method.load(gpu, default_shader_dir(), error) || !tracer.build(scene, error)) {
      std::fprintf(stderr, "%s: %s\n", name, error.c_str());
      continue;
    }
    method.settings().intersect = MeshIntersection::kBvh;
    render_image(method, scene.camera, 8, 8, 1);  // loads the BVHs
    double field_mb = 0.0, bvh_mb = 0.0;
    asset_bytes(gpu, field_mb, bvh_mb);
    std::printf(
        "\n## %s\n\nGPU memory of the meshes: geometry images + fields %.1f MB; BVHs + "
        "rasterised meshes %.1f MB (BVH build %.3f s)\n",
        name, field_mb, bvh_mb, gpu.assets().bvhs().build_seconds());
    for (int size : arguments.sizes)
      for (int depth : depths)
        bench_depth(method, tracer, scene, size, depth, frames);
  }
  return 0;
}
