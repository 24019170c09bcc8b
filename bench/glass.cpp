// The paper's Tables 1-3 (Mukai et al. 2013) on this machine: frame time of the glass method
// (runtime/methods/glass.hpp, headless OpenGL) against the number of vertices behind the glass
// (100K-800K) for a parallel plate (Table 1) and a hollow cylinder (Table 2: worst, best and
// mean over camera positions), and against the resolution (640x480-1600x1200, 100K vertices,
// Table 3); beside the reference tracer (`gfield render`, 1 sample per pixel) on the same frames.
//
// Frame times: wall and GPU, median and range of the timed frames after warm-up frames until two
// agree (runtime/frame_timing.hpp).
//
//   bench_glass [--quick] [--vertices N,N,...] [--frames F] [--azimuths A]
//   (default: 100K-800K in steps of 100K, 10 timed frames, 4 azimuths, four resolutions;
//   --quick: 100K-400K, 2 timed frames, 2 azimuths, two resolutions; an option given keeps its
//   value)

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "gfield/scene.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/frame_timing.hpp"
#include "runtime/gl_context.hpp"
#include "runtime/methods/glass.hpp"
#include "runtime/shader_program.hpp"
#include "time_text.hpp"

namespace {

using namespace gfield;
namespace fs = std::filesystem;

/// A UV sphere of about `vertices` vertices written as OBJ (the object behind the glass).
void write_sphere(const fs::path& file, int vertices) {
  const int rings = std::max(4, int(std::sqrt(vertices / 2.0)));
  const int segments = std::max(8, vertices / rings);
  std::ofstream out(file);
  const double pi = 3.14159265358979323846;
  for (int j = 0; j < rings; ++j) {
    const double e = pi * ((j + 0.5) / rings - 0.5);
    for (int i = 0; i < segments; ++i) {
      const double a = 2.0 * pi * i / segments;
      out << "v " << std::cos(e) * std::sin(a) << ' ' << std::sin(e) << ' '
          << std::cos(e) * std::cos(a) << '\n';
    }
  }
  for (int j = 0; j + 1 < rings; ++j) {
    for (int i = 0; i < segments; ++i) {
      const int a = j * segments + i + 1, b = j * segments + (i + 1) % segments + 1;
      const int c = a + segments, d = b + segments;
      out << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
    }
  }
}

/// The plate scene of Figure 9 (30 degrees, W = 1) or the hollow cylinder of Figure 1, with the
/// sphere mesh `mesh` behind the glass and no floor (every vertex is the object's).
std::string scene_text(bool cylinder, const fs::path& mesh) {
  const std::string glass =
      cylinder ? R"({"name": "glass", "shape": "hollow-cylinder", "radius": 1.0, "thickness": 0.08,
                     "height": 2.2, "transform": {"translate": [0, 1.1, 0]},
                     "material": {"type": "dielectric", "ior": 1.5}})"
               : R"({"name": "plate", "shape": "slab", "size": [2.0, 3.0], "thickness": 1.0,
                     "transform": {"translate": [0.3, 1.1, 1.0], "rotate": [0, 30, 0]},
                     "material": {"type": "dielectric", "ior": 1.5}})";
  const std::string object_transform = cylinder ? R"({"translate": [0, 1.0, -1.6], "scale": 0.6})"
                                                : R"({"translate": [0, 1.0, -1.5], "scale": 0.8})";
  return R"({"camera": {"position": [0, 1.6, 8], "target": [0, 1.0, 0], "fov": 35},
  "image": {"width": 640, "height": 480}, "environment": {"type": "studio"}, "ambient": 0.35,
  "lights": [{"type": "directional", "direction": [-0.3, -1, -0.6], "intensity": 0.8}],
  "objects": [)" +
         glass + R"(, {"name": "ball", "shape": "mesh", "file": ")" + mesh.string() +
         R"(", "transform": )" + object_transform +
         R"(, "material": {"type": "diffuse", "color": [0.85, 0.55, 0.25]}}]})";
}

struct Timing {
  TimeSummary wall, gpu;      ///< the glass method's timed frames, ms
  double reference_ms = 0.0;  ///< one reference-tracer frame (1 spp, full Fresnel)
  int class_images = 0;
  long long vertices = 0;
};

Timing time_glass(const Scene& scene, int width, int height, int frames) {
  Timing t;
  std::string error;
  GpuScene gpu;
  GlassMethod glass;
  if (!gpu.load(scene, error) || !glass.load(gpu, default_shader_dir(), error)) {
    std::fprintf(stderr, "bench_glass: %s\n", error.c_str());
    std::exit(2);
  }
  const FrameTimes times = time_frames(
      [&](FrameStats* stats) { render_image(glass, scene.camera, width, height, 1, stats); },
      frames);
  t.wall = summarize(times.wall_ms);
  t.gpu = summarize(times.gpu_ms);
  t.class_images = int(times.stats.count("class images")) / frames;
  t.vertices = (long long)(times.stats.count("opaque vertices")) / frames;
  ReferenceTracer tracer;
  if (!tracer.build(scene, error)) {
    std::fprintf(stderr, "bench_glass: %s\n", error.c_str());
    std::exit(2);
  }
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.samples_per_pixel = 1;
  options.jitter = false;
  RenderStats reference;
  tracer.render(options, &reference);
  t.reference_ms = reference.seconds * 1e3;
  return t;
}

Scene make_scene(bool cylinder, const fs::path& dir, int vertices) {
  const fs::path mesh = dir / ("sphere-" + std::to_string(vertices) + ".obj");
  if (!fs::exists(mesh))
    write_sphere(mesh, vertices);
  const fs::path file = dir / (cylinder ? "cylinder.json" : "plate.json");
  std::ofstream(file) << scene_text(cylinder, mesh);
  Scene scene;
  std::string error;
  if (!load_scene(file.string(), scene, error, OutsidePaths::kAllowed)) {
    std::fprintf(stderr, "bench_glass: %s\n", error.c_str());
    std::exit(2);
  }
  return scene;
}

double fps(double ms) {
  return 1000.0 / std::max(ms, 1e-9);
}

/// A row of Tables 1 and 3: `what`, then the glass method's times against the reference's.
void print_row(const std::string& what, const Timing& t) {
  std::printf("| %s | %s | %s | %.2f | %.1f | %.2f | %.2fx |\n", what.c_str(),
              range_text(t.wall).c_str(), range_text(t.gpu).c_str(), fps(t.wall.median),
              t.reference_ms, fps(t.reference_ms), t.reference_ms / t.wall.median);
}

}  // namespace

/// Table 1: the parallel plate at 640x480 against the vertices behind it.
void plate_table(const fs::path& dir, const std::vector<int>& counts, int frames) {
  std::printf("\nTable 1: parallel plate (30 deg, W = 1.0), 640x480\n\n");
  std::printf(
      "| vertices | glass ms (min-max) | GPU ms (min-max) | FPS | reference ms | ref FPS | "
      "speed-up |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int n : counts) {
    const Timing t = time_glass(make_scene(false, dir, n), 640, 480, frames);
    print_row(std::to_string(t.vertices), t);
  }
}

/// Table 2: the hollow cylinder at 640x480 against the vertices behind it, over camera azimuths.
void cylinder_table(const fs::path& dir, const std::vector<int>& counts, int frames, int azimuths) {
  std::printf(
      "\nTable 2: hollow cylinder, 640x480, FPS (of the median frame) over %d camera "
      "azimuths\n\n",
      azimuths);
  std::printf(
      "| vertices | worst | best | mean | images | ref FPS | speed-up | widest range |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const int n : counts) {
    Scene scene = make_scene(true, dir, n);
    double worst = 1e30, best = 0.0, sum = 0.0, ref_sum = 0.0, spread = 0.0;
    int images = 0;
    long long vertices = 0;
    for (int k = 0; k < azimuths; ++k) {
      const double a = 0.35 * k;
      scene.camera.position = glm::vec3(8.0f * std::sin(a), 1.6f, 8.0f * std::cos(a));
      const Timing t = time_glass(scene, 640, 480, frames);
      worst = std::min(worst, fps(t.wall.median));
      best = std::max(best, fps(t.wall.median));
      sum += t.wall.median;
      spread = std::max(spread, t.wall.spread());
      ref_sum += t.reference_ms;
      images = std::max(images, t.class_images);
      vertices = t.vertices;
    }
    std::printf("| %lld | %.2f | %.2f | %.2f | %d | %.2f | %.2fx | %.0f%%%s |\n", vertices, worst,
                best, fps(sum / azimuths), images, fps(ref_sum / azimuths), ref_sum / sum,
                spread * 100.0, spread > kMaxSpread ? "*" : "");
  }
}

/// Table 3: the hollow cylinder with 100K vertices behind it against the resolution.
void resolution_table(const fs::path& dir, bool quick, int frames) {
  std::printf("\nTable 3: hollow cylinder, 100K vertices, against the resolution\n\n");
  std::printf(
      "| resolution | glass ms (min-max) | GPU ms (min-max) | FPS | reference ms | ref FPS "
      "| speed-up |\n|---:|---:|---:|---:|---:|---:|---:|\n");
  const std::vector<glm::ivec2> sizes =
      quick ? std::vector<glm::ivec2>{{640, 480}, {1600, 1200}}
            : std::vector<glm::ivec2>{{640, 480}, {800, 600}, {1024, 768}, {1600, 1200}};
  const Scene scene = make_scene(true, dir, 100000);
  for (const glm::ivec2 s : sizes) {
    const Timing t = time_glass(scene, s.x, s.y, frames);
    print_row(std::to_string(s.x) + "x" + std::to_string(s.y), t);
  }
}

/// Comma-separated positive integers, e.g. "100000,200000"; empty on a malformed list.
std::vector<int> parse_counts(const char* text) {
  std::vector<int> counts;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const long n = std::strtol(item.c_str(), &end, 10);
    if (end == item.c_str() || *end != 0 || n <= 0 || n > 100000000)
      return {};
    counts.push_back(int(n));
  }
  return counts;
}

int main(int argc, char** argv) {
  bool quick = false;
  std::vector<int> counts = {100000, 200000, 300000, 400000, 500000, 600000, 700000, 800000};
  int frames = 10, azimuths = 4;
  bool set_vertices = false, set_frames = false, set_azimuths = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
    bool ok = true;
    if (arg == "--quick") {
      quick = true;
    } else if (arg == "--vertices" && value != nullptr) {
      counts = parse_counts(value);
      ok = !counts.empty();
      set_vertices = true;
      ++i;
    } else if (arg == "--frames" && value != nullptr) {
      frames = std::atoi(value);
      ok = frames > 0;
      set_frames = true;
      ++i;
    } else if (arg == "--azimuths" && value != nullptr) {
      azimuths = std::atoi(value);
      ok = azimuths > 0;
      set_azimuths = true;
      ++i;
    } else {
      ok = false;
    }
    if (!ok) {
      std::fprintf(stderr,
                   "usage: bench_glass [--quick] [--vertices N,N,...] [--frames F] "
                   "[--azimuths A]\n");
      return 2;
    }
  }
  if (quick) {
    counts = set_vertices ? counts : std::vector<int>{100000, 200000, 400000};
    frames = set_frames ? frames : 2;
    azimuths = set_azimuths ? azimuths : 2;
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they are measured
  std::string error;
  auto context = GlContext::create_headless(error);
  if (!context) {
    std::fprintf(stderr, "bench_glass: %s\n", error.c_str());
    return 3;
  }
  const fs::path dir = fs::temp_directory_path() / "gfield_bench_glass";
  fs::create_directories(dir);
  std::printf("renderer: %s (%s, %s); reference tracer: Embree on the CPU, 1 spp\n",
              context->renderer().c_str(), context->version().c_str(), context->platform().c_str());
  std::printf("%d timed frame(s) per row; %s\n", frames, kFrameTimeNote);

  plate_table(dir, counts, frames);
  cylinder_table(dir, counts, frames, azimuths);
  resolution_table(dir, quick, frames);
  return 0;
}
