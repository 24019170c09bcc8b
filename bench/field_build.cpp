// Geometry-field build against its floors, and the compact layout's memory against the layered
// one's, in one run, per mesh: the bare Embree first-hit cast of the same rays (same packets,
// nothing stored), the build's own line traversals storing nothing (kMaxLineHits + 1 hits from
// each line's lower sample, a second traversal for lines with more), and the build (traversals,
// uvs, the compact layout). Then the field's GPU bytes at 8 bits, compact (format 3) against the
// layered K = 4 of format 2; the EXR writes of both, timed, with their file sizes; and the
// lines whose every hit each layout holds. Usage: bench_field_build [N] [repetitions] [MESH...]
// (N = 24, 3 repetitions, every bundled mesh of data/meshes by default, each through the real
// pipeline at its default image size).
//
// Wall times grow with whatever else runs on the machine; the process CPU seconds divided by the
// hardware threads estimate the time on an otherwise idle machine, and are printed beside them.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "bench/bench_assets.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/gpu_storage.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/field_build.hpp"
#include "test_support/build_paths.hpp"

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

/// The bundled meshes (data/meshes/*.obj, not the .gimage.obj of an asset), by name.
std::vector<std::string> bundled_meshes() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(gfield::build_paths::mesh_dir())) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() == ".obj" && name.find(".gimage.") == std::string::npos) {
      files.push_back(name);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Best time and the file's megabytes of writing `field` with `save`.
std::pair<Timing, double> timed_write(const std::string& path, int repetitions, const auto& save) {
  Timing write;
  std::string error;
  for (int r = 0; r < repetitions; ++r) {
    write.run([&] {
      if (!save(path, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
      }
    });
  }
  std::error_code ec;
  const double megabytes = double(std::filesystem::file_size(path, ec)) / 1e6;
  std::filesystem::remove(path, ec);
  return {write, megabytes};
}

}  // namespace

int main(int argc, char** argv) {
  using namespace gfield;
  const int n = argc > 1 ? std::atoi(argv[1]) : 24;
  const int repetitions = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  std::vector<std::string> meshes(argv + std::min(argc, 3), argv + argc);
  if (meshes.empty()) {
    meshes = bundled_meshes();
  }
  const double threads = double(std::max(1u, std::thread::hardware_concurrency()));
  std::printf("field build, N = %d (%d x %d pairs), %g hardware threads, best of %d\n", n,
              sample_count(n), sample_count(n), threads, repetitions);
  std::printf("%-16s %8s %8s %8s %8s %6s %6s | %8s %8s %6s | %7s %7s %7s %7s | %7s %7s\n", "mesh",
              "faces", "bare [s]", "lines[s]", "build[s]", "/bare", "/lines", "GPU3[MB]",
              "GPU2[MB]", "ratio", "w3 [s]", "f3 [MB]", "w2 [s]", "f2 [MB]", "all<=8", "all<=4");
  int failures = 0;
  for (const std::string& file : meshes) {
    BenchAsset asset;
    if (!load_bench_asset(file, kAutoImageSize, asset)) {
      ++failures;
      continue;
    }
    std::string error;
    EmbreeMesh embree;
    if (!embree.build(asset.pm.mesh, error)) {
      std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
      return 1;
    }
    Timing bare, lines, build;
    size_t bare_hits = 0, line_hits = 0;
    GeometryField field;
    FieldBuildStats stats;
    for (int r = 0; r < repetitions; ++r) {  // interleaved, so that load changes hit all alike
      bare.run([&] { bare_hits = cast_field_rays(embree, asset.image.box, n); });
      lines.run([&] { line_hits = cast_field_rays(embree, asset.image.box, n, true); });
      // Every build fills a new field, as one `gfield field` does (its table's pages are first
      // touched inside the build); the field before it is freed outside the timing.
      GeometryField fresh;
      build.run(
          [&] { build_geometry_field(asset.pm, embree, asset.image, n, fresh, error, &stats); });
      field = std::move(fresh);
    }
    // The build's traversals and the build meet the same rays; the bare cast of every ray
    // differs where a grazing ray slips between two triangles in one direction only.
    if (line_hits != stats.hits ||
        std::max(bare_hits, line_hits) - std::min(bare_hits, line_hits) > stats.hits / 10000) {
      std::fprintf(stderr, "%s: bare cast, traversals and build disagree (%zu, %zu, %zu hits)\n",
                   file.c_str(), bare_hits, line_hits, stats.hits);
      ++failures;
    }
    field.source = asset.image.source;
    const std::string path =
        (std::filesystem::temp_directory_path() / ("bench_" + asset.name + ".gfield.exr")).string();
    const auto [w3, f3] = timed_write(path, repetitions, [&](const std::string& p, std::string& e) {
      return save_geometry_field(p, field, ExrPrecision::kHalf, e);
    });
    const auto [w2, f2] = timed_write(path, repetitions, [&](const std::string& p, std::string& e) {
      return save_layered_geometry_field(p, field, kMaxFieldLayers, ExrPrecision::kHalf, e);
    });
    const double gpu3 = double(field_gpu_bytes(field, 8)) / 1e6;
    const double gpu2 = double(layered_field_gpu_bytes(n, kMaxFieldLayers, 8)) / 1e6;
    std::printf(
        "%-16s %8zu %8.3f %8.3f %8.3f %6.3f %6.3f | %8.1f %8.1f %6.3f | %7.3f %7.1f %7.3f %7.1f | "
        "%6.3f%% %6.3f%%\n",
        asset.name.c_str(), asset.pm.mesh.triangles.size(), bare.wall, lines.wall, build.wall,
        build.wall / bare.wall, build.wall / lines.wall, gpu3, gpu2, gpu3 / gpu2, w3.wall, f3,
        w2.wall, f2, 100.0 * layer_coverage(stats, kMaxLineHits),
        100.0 * layer_coverage(stats, kMaxFieldLayers));
    std::printf(
        "%-16s CPU s / %g: %6.3f %8.3f %8.3f   %d^2 image, %.1f%% of %zu rays hit, up to %d "
        "hits a line, %zu line-table words, %zu interior hits\n",
        "", threads, bare.cpu / threads, lines.cpu / threads, build.cpu / threads, asset.image.size,
        100.0 * double(stats.hits) / double(stats.rays), stats.rays, field.layers,
        field.lines.size(), field.interior.size());
  }
  std::printf(
      "/bare, /lines: the build over the bare first-hit cast and over its own traversals storing\n"
      "nothing; GPU3, GPU2: the field at 8 bits, compact and layered K = 4 (ratio: 3 / 2); w3, "
      "f3,\n"
      "w2, f2: EXR write time and file size of each (half floats); all<=8, all<=4: lines whose\n"
      "every hit the compact field (up to 8 a line) and K = 4 hold\n");
  return failures == 0 ? 0 : 1;
}
