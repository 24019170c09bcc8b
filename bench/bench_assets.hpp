#pragma once
// The bundled test meshes (data/meshes) of the benchmarks through the real geometry-image pipeline
// (at a given size or kAutoImageSize, measurements off): the parameterised mesh and the geometry
// image of each.

#include <cstdio>
#include <filesystem>
#include <string>

#include "preprocess/geometry_image_build.hpp"
#include "test_support/build_paths.hpp"

namespace gfield {

struct BenchAsset {
  std::string name;
  ParameterizedMesh pm;
  GeometryImage image;
};

/// Loads `file` from data/meshes and builds its geometry image; false (with a message on
/// stderr) when the mesh is missing or the pipeline fails.
inline bool load_bench_asset(const std::string& file, int image_size, BenchAsset& asset) {
  const std::string path = std::string(gfield::build_paths::mesh_dir()) + "/" + file;
  TriangleMesh mesh;
  std::string error;
  if (!load_mesh(path, mesh, error)) {
    std::fprintf(stderr, "skipping %s: %s\n", file.c_str(), error.c_str());
    return false;
  }
  GeometryImageOptions options;
  options.size = image_size;
  options.measure = false;
  GeometryImageReport report;
  if (!build_geometry_image(mesh, options, asset.image, asset.pm, report, error)) {
    std::fprintf(stderr, "skipping %s: %s\n", file.c_str(), error.c_str());
    return false;
  }
  asset.name = std::filesystem::path(file).stem().string();
  asset.image.source = file;
  return true;
}

}  // namespace gfield
