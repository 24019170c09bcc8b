// Geometry-field build vs a bare Embree first-hit cast of the very same rays (same packets,
// nothing stored), in one run, per mesh, for K = 1 (first hits only) and K = 2 (one traversal per
// line collecting up to 5 hits, a second from the exit for lines with more); for K = 2 also
// against its physical floor, the same traversals storing nothing. Then the default build (K
// chosen, 5 hits looked for) once. The EXR write of the K = 2 field is timed on its own. Usage:
// bench_field_build [N] [repetitions] (N = 24 by default, meshes spot, homer and the bunny through
// the real pipeline at its default image size: 512^2, 1024^2, 1024^2).
//
// Wall times grow with whatever else runs on the machine; the process CPU seconds divided by the
// hardware threads estimate the time on an otherwise idle machine, and are printed beside them.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <thread>

#include "bench/bench_assets.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/field_build.hpp"

namespace {

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// Best wall and best CPU seconds of repeated runs of one job.
struct Timing {
  double wall = 1e30;
  double cpu = 1e30;

  void run(const auto& work) {
    const double cpu_start = process_cpu_seconds();
    gfield::Stopwatch watch;
    work();
    wall = std::min(wall, watch.seconds());
    cpu = std::min(cpu, process_cpu_seconds() - cpu_start);
  }
};

}  // namespace

int main(int argc, char** argv) {
  using namespace gfield;
  const int n = argc > 1 ? std::atoi(argv[1]) : 24;
  const int repetitions = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  const double threads = double(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("field build, N = %d (%d x %d pairs), %g hardware threads, best of %d\n", n,
              sample_count(n), sample_count(n), threads, repetitions);
  std::printf("%-16s %8s %9s %9s %7s %9s %9s %7s %7s %9s %9s\n", "mesh", "faces", "bare [s]",
              "K=1 [s]", "ratio", "2-hit [s]", "K=2 [s]", "ratio", "/2-hit", "write [s]",
              "file [MB]");
  int failures = 0;
  for (const char* file : {"spot.obj", "homer.obj", "stanford-bunny.obj"}) {
    BenchAsset asset;
    if (!load_bench_asset(file, kAutoImageSize, asset)) {
      ++failures;
      continue;
    }
    std::string error;
    EmbreeMesh embree;
    Timing bvh;
    bvh.run([&] {
      if (!embree.build(asset.pm.mesh, error)) {
        std::fprintf(stderr, "%s: %s\n", file, error.c_str());
        std::exit(1);
      }
    });
    Timing bare, bare2, build1, build2;
    size_t bare_hits = 0, bare2_hits = 0;
    GeometryField field;
    FieldBuildStats stats1, stats2;
    // Every build fills a new field, as one `gfield field` does (its table's pages are first
    // touched inside the build); the field before it is freed outside the timing.
    const auto timed_build = [&](Timing& timing, int layers, FieldBuildStats& stats) {
      GeometryField fresh;
      timing.run([&] {
        build_geometry_field(asset.pm, embree, asset.image, n, layers, fresh, error, &stats);
      });
      field = std::move(fresh);
    };
    for (int r = 0; r < repetitions; ++r) {  // interleaved, so that load changes hit all alike
      bare.run([&] { bare_hits = cast_field_rays(embree, asset.image.box, n); });
      bare2.run([&] { bare2_hits = cast_field_rays(embree, asset.image.box, n, 2); });
      timed_build(build1, 1, stats1);
      timed_build(build2, 2, stats2);
    }
    if (bare_hits != stats1.hits || bare_hits != stats2.hits || bare2_hits != bare_hits) {
      std::fprintf(stderr, "%s: bare cast and builds disagree (%zu vs %zu, %zu hits)\n", file,
                   bare_hits, stats1.hits, stats2.hits);
      ++failures;
    }
    field.source = asset.image.source;
    const std::string path =
        (std::filesystem::temp_directory_path() / ("bench_" + asset.name + ".gfield.exr")).string();
    Timing write;
    for (int r = 0; r < std::min(repetitions, 3); ++r) {
      write.run([&] {
        if (!save_geometry_field(path, field, ExrPrecision::kHalf, error)) {
          std::fprintf(stderr, "%s\n", error.c_str());
        }
      });
    }
    std::error_code ec;
    const double megabytes = double(std::filesystem::file_size(path, ec)) / 1e6;
    std::filesystem::remove(path, ec);
    std::printf("%-16s %8zu %9.3f %9.3f %7.3f %9.3f %9.3f %7.3f %7.3f %9.3f %9.1f\n",
                asset.name.c_str(), asset.pm.mesh.triangles.size(), bare.wall, build1.wall,
                build1.wall / bare.wall, bare2.wall, build2.wall, build2.wall / bare.wall,
                build2.wall / bare2.wall, write.wall, megabytes);
    std::printf("%-16s CPU s / %g: %9.3f %9.3f %7.3f %9.3f %9.3f %7.3f %7.3f   (BVH %.3f s)\n", "",
                threads, bare.cpu / threads, build1.cpu / threads, build1.cpu / bare.cpu,
                bare2.cpu / threads, build2.cpu / threads, build2.cpu / bare.cpu,
                build2.cpu / bare2.cpu, bvh.wall);
    Timing chosen;
    FieldBuildStats stats;
    timed_build(chosen, kAutoLayers, stats);
    std::printf(
        "%-16s %d^2 image, %zu rays, %.1f%% hit, bare %.1f Mrays/s; default build %.3f s (ratio"
        " %.3f): K = %d, lines holding all hits with K = 1..4: %.3f %.3f %.3f %.3f%%\n",
        "", asset.image.size, stats.rays, 100.0 * double(stats.hits) / double(stats.rays),
        double(stats.rays) / bare.wall / 1e6, chosen.wall, chosen.wall / bare.wall, stats.layers,
        100.0 * layer_coverage(stats, 1), 100.0 * layer_coverage(stats, 2),
        100.0 * layer_coverage(stats, 3), 100.0 * layer_coverage(stats, 4));
  }
  std::printf(
      "targets: K = 2 build <= 1.5 x the bare first-hit cast (ratio); /2-hit: the K = 2\n"
      "build over the bare two-hit traversal of the same rays (its physical floor)\n");
  return failures == 0 ? 0 : 1;
}
