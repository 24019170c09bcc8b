// bench_reference_tracer [SCENE.json ...]: renders every example scene (data/scenes, or the
// given files) at 512 x 512, 8 spp, depth 10, full dielectric mode, and prints the time, the
// rays traced (camera + reflected/refracted + shadow) and Mrays/s, beside the physical
// reference measured in the same run: the raw first-hit casts of the same camera rays
// (Embree + analytic primitives, no shading), as Mrays/s and as the ratio render/raw per ray.
// On a shared machine wall-clock rates depend on the load, so the rate per CPU-second (process
// CPU time, all threads) is printed too: on 2 idle cores the wall rate approaches 2x that.

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "gfield/scene.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/reference_tracer.hpp"
#include "test_support/build_paths.hpp"

namespace {

/// CPU seconds used by this process so far (user + system, all threads).
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i)
    files.emplace_back(argv[i]);
  if (files.empty()) {
    for (const auto& entry :
         fs::directory_iterator(fs::path(gfield::build_paths::data_dir()) / "scenes")) {
      if (entry.path().extension() == ".json")
        files.push_back(entry.path().string());
    }
    std::sort(files.begin(), files.end());
  }
  gfield::RenderOptions options;
  options.width = options.height = 512;
  options.samples_per_pixel = 8;
  options.max_depth = 10;
  std::printf("reference tracer, 512x512, 8 spp, depth 10, --dielectric full\n");
  std::printf("%-28s %8s %9s %8s %8s %11s %10s %8s\n", "scene", "build s", "render s", "Mrays",
              "Mrays/s", "Mrays/cpu-s", "raw Mray/s", "cost/ray");
  double total_seconds = 0.0, total_rays = 0.0, total_cpu = 0.0;
  for (const std::string& file : files) {
    gfield::Scene scene;
    std::string error;
    if (!gfield::load_scene(file, scene, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    gfield::ReferenceTracer tracer;
    gfield::Stopwatch watch;
    if (!tracer.build(scene, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    const double build = watch.seconds();
    const gfield::RenderStats raw = tracer.cast_camera_rays(options);
    gfield::RenderStats stats;
    const double cpu0 = cpu_seconds();
    tracer.render(options, &stats);
    const double cpu = cpu_seconds() - cpu0;
    const double rays = double(stats.total_rays());
    const double rate = rays / stats.seconds / 1e6;
    const double raw_rate = double(raw.camera_rays) / raw.seconds / 1e6;
    std::printf("%-28s %8.3f %9.2f %8.2f %8.2f %11.2f %10.2f %8.2f\n",
                fs::path(file).stem().string().substr(0, 28).c_str(), build, stats.seconds,
                rays / 1e6, rate, rays / cpu / 1e6, raw_rate, raw_rate / rate);
    total_seconds += stats.seconds;
    total_cpu += cpu;
    total_rays += rays;
  }
  std::printf("all scenes: %.2f s (%.2f CPU s), %.1f Mrays, %.2f Mrays/s, %.2f Mrays/cpu-s\n",
              total_seconds, total_cpu, total_rays / 1e6, total_rays / total_seconds / 1e6,
              total_rays / total_cpu / 1e6);
  return 0;
}
