// Geometry image build times per stage: mesh file -> 512^2 geometry image (target: the
// 70K-face bunny in <= 3 s on a 2-core machine). Reference measured in the same run:
// reading the mesh file (load_mesh), so the ratio is "image build time in mesh loads".
//
// Usage: bench_geometry_image [MESH ...] [--size N] [--runs R]
// Prints the median of R runs (default 3) of every stage, without and then with measurements.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "geometry/mesh_io.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/geometry_image_build.hpp"
#include "test_support/build_paths.hpp"

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> meshes;
  int size = 512, runs = 3;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--size" && a + 1 < argc)
      size = std::atoi(argv[++a]);
    else if (arg == "--runs" && a + 1 < argc)
      runs = std::max(1, std::atoi(argv[++a]));
    else
      meshes.push_back(arg);
  }
  if (meshes.empty())
    meshes.push_back(std::string(gfield::build_paths::mesh_dir()) + "/stanford-bunny.obj");

  std::printf("%-22s %7s %8s %8s %8s %8s %8s %8s %8s %9s %8s\n", "mesh", "faces", "load_s",
              "repair_s", "param_s", "pack_s", "raster_s", "file2img", "ratio", "measure_s",
              "charts");
  for (const std::string& path : meshes) {
    std::vector<double> load, repair, parameterize, pack, rasterize, total;
    gfield::GeometryImageReport report;
    size_t faces = 0;
    for (int run = 0; run < runs; ++run) {
      gfield::Stopwatch watch;
      gfield::TriangleMesh mesh;
      std::string error;
      if (!gfield::load_mesh(path, mesh, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
      }
      load.push_back(watch.seconds());
      faces = mesh.triangles.size();
      gfield::GeometryImageOptions options;
      options.size = size;
      options.measure = false;
      gfield::GeometryImage image;
      gfield::ParameterizedMesh pm;
      if (!gfield::build_geometry_image(mesh, options, image, pm, report, error)) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
        return 1;
      }
      total.push_back(watch.seconds());
      repair.push_back(report.seconds.repair);
      parameterize.push_back(report.seconds.parameterize);
      pack.push_back(report.seconds.pack);
      rasterize.push_back(report.seconds.rasterize);
    }
    // One run with the measurements (distortion, 2 x 100K-sample reconstruction error).
    gfield::TriangleMesh mesh;
    std::string error;
    gfield::load_mesh(path, mesh, error);
    gfield::GeometryImageOptions options;
    options.size = size;
    gfield::GeometryImage image;
    gfield::ParameterizedMesh pm;
    gfield::build_geometry_image(mesh, options, image, pm, report, error);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    std::printf("%-22s %7zu %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.1f %9.3f %8zu\n", name.c_str(),
                faces, median(load), median(repair), median(parameterize), median(pack),
                median(rasterize), median(total), median(total) / median(load),
                report.seconds.measure, report.charts.size());
  }
  std::printf(
      "file2img = load + build without measurements (median of %d runs); ratio = file2img "
      "/ load; image %d^2\n",
      runs, size);
  return 0;
}
