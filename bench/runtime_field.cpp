// gfield-view's geometry-field method against its peer and its floor, on this machine's GL
// (llvmpipe on the CI machine): per example scene, picture size and depth, ms per frame with
// the meshes looked up in their geometry fields (refined; at depth 4 also nearest and linear)
// and traced exactly through BVHs of their triangles (--intersect bvh), each against the Embree
// reference tracer's time for the same picture (1 spp, same depth) in the same run, the PSNR of
// each against that reference, the GPU bytes of each (geometry image + field against BVH + the
// rasterised mesh, which both draw), secondary rays per traced pixel, and the work each does
// (field texel and image texel fetches and Newton steps per lookup, nodes and triangles per BVH
// traversal: counted on the GPU, independent of the device), each in both tracing passes (a
// compute dispatch and a fragment pass: methods/trace_pass.hpp), wall and GPU times as median
// and range. Prints markdown tables. Assets are built with `gfield build` (its defaults, as
// scripts/demo.sh) into a temporary folder.
//
// Usage: bench_runtime_field [--frames F] [--depths D,D,...] [--passes compute,fragment] [SIZE...]
//        (default: 2 frames, depths 1,2,4, both passes, sizes 512 1024)

#include <algorithm>
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

void print_row(const char* what, TracePass pass, const Run& r, const ReferenceTime& reference) {
  const double traced = r.per_sample.count("traced pixels");
  std::printf("| %s | %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %s |\n", what,
              trace_pass_name(pass), range_text(r.wall).c_str(), range_text(r.gpu).c_str(),
              r.ms / reference.ms, r.cpu_ms / reference.cpu_ms, r.psnr,
              traced > 0.0 ? r.per_sample.count("secondary rays") / traced : 0.0,
              work_line(r.per_sample).c_str());
}

/// The rows of one scene, size and depth: per tracing pass, the field (refined; at depth 4 in
/// the first pass also nearest and linear) and the BVH.
void bench_depth(GeometryFieldMethod& method, ReferenceTracer& tracer, const Scene& scene, int size,
                 int depth, int frames, const std::vector<TracePass>& passes) {
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
      "| intersection | pass | ms/frame (min-max) | GPU ms (min-max) | x reference | x reference "
      "(CPU time) | PSNR dB | rays / traced pixel | work |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  method.settings().max_depth = depth;
  std::vector<Run> field, bvh;  // refined and BVH, per pass
  for (TracePass pass : passes) {
    method.settings().pass = pass;
    method.settings().intersect = MeshIntersection::kField;
    for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
      if (mode != LookupMode::kRefined && (depth != 4 || pass != passes.front()))
        continue;
      method.settings().mode = mode;
      const Run r = run(method, scene, size, frames, reference);
      print_row((std::string("field, ") + lookup_mode_name(mode)).c_str(), pass, r, reference_time);
      if (mode == LookupMode::kRefined)
        field.push_back(r);
    }
    method.settings().intersect = MeshIntersection::kBvh;
    bvh.push_back(run(method, scene, size, frames, reference));
    print_row("bvh (exact)", pass, bvh.back(), reference_time);
    std::fflush(stdout);
  }
  method.settings().intersect = MeshIntersection::kField;
  std::printf("\nfield (refined) / BVH, GPU time:");
  for (size_t k = 0; k < passes.size(); ++k)
    std::printf("%s %s %.2f", k == 0 ? "" : ";", trace_pass_name(passes[k]),
                field[k].gpu_ms / bvh[k].gpu_ms);
  if (passes.size() == 2)
    std::printf(". %s / %s, GPU time: field %.2f, BVH %.2f", trace_pass_name(passes[0]),
                trace_pass_name(passes[1]), field[0].gpu_ms / field[1].gpu_ms,
                bvh[0].gpu_ms / bvh[1].gpu_ms);
  std::printf("\n%s\n", kFrameTimeNote);
  std::fflush(stdout);
}

/// "compute", "fragment", or both separated by a comma, in the order given.
bool parse_passes(const std::string& text, std::vector<TracePass>& passes) {
  passes.clear();
  for (size_t start = 0; start <= text.size();) {
    const size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    const TracePass pass = name == "compute" ? TracePass::kCompute : TracePass::kFragment;
    if ((name != "compute" && name != "fragment") ||
        std::find(passes.begin(), passes.end(), pass) != passes.end())
      return false;
    passes.push_back(pass);
    start = end + 1;
  }
  return true;
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
  std::vector<TracePass> passes = {TracePass::kCompute, TracePass::kFragment};
  std::vector<char*> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--passes" && i + 1 < argc) {
      if (!parse_passes(argv[++i], passes)) {
        std::fprintf(stderr, "--passes %s: expected compute, fragment or both (a,b)\n", argv[i]);
        return 2;
      }
    } else if (std::string(argv[i]) == "--depths" && i + 1 < argc) {
      if (!parse_depths(argv[++i], depths)) {
        std::fprintf(stderr, "--depths %s: expected D,D,... in [0, 64]\n", argv[i]);
        return 2;
      }
    } else {
      rest.push_back(argv[i]);
    }
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows reach a file as they are measured
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
        bench_depth(method, tracer, scene, size, depth, frames, passes);
  }
  return 0;
}
