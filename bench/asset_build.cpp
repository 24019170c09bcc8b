// Whole asset builds (`gfield build`, defaults) against their floor, in one run, per mesh: the
// build's stages (mesh read, image with its proxy, repair, parameterisation and measurement, image
// write, field casts, field write, verify), its peak memory, and the floor: the parameterisation
// the build did (the proxy's where it used one) plus the bare Embree first-hit cast of the field's
// rays on the mesh the field was cast on (cast_field_rays, timed here). Meshes: spot, homer and
// the Stanford bunny of data/meshes, and the bunny split into 3 x 3 and 6 x 6 on its PN patches
// (pn_subdivision.hpp: 625K and 2.5M faces, smooth as a scan), written by the benchmark into its
// folder. Usage: bench_asset_build [MESH...] (paths; default: those five).
//
// Times are wall seconds of one build each on an otherwise idle machine; the build runs as its
// own process (its peak resident memory from wait4).

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/build_runs.hpp"
#include "bench/example_scenes.hpp"
#include "bench/pn_subdivision.hpp"
#include "geometry/parameterized_mesh.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/field_build.hpp"
#include "test_support/build_paths.hpp"

namespace {

using namespace gfield;

/// Seconds of the bare first-hit cast of the field's rays on the asset's parameterised mesh.
double bare_cast_seconds(const std::string& name, int samples_per_side) {
  GeometryImage image;
  ParameterizedMesh pm;
  EmbreeMesh embree;
  std::string error;
  if (!load_geometry_image(name + ".gimage.exr", image, error) ||
      !load_parameterized_mesh_of(image, name + ".gimage.exr", pm, error) ||
      !embree.build(pm.mesh, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 0.0;
  }
  const Stopwatch watch;
  cast_field_rays(embree, image.box, samples_per_side);
  return watch.seconds();
}

/// The bunny split k x k on its PN patches, written into `dir`; its path ("" on failure).
std::string subdivided_bunny(const std::filesystem::path& dir, int k) {
  TriangleMesh bunny;
  std::string error;
  if (!load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/stanford-bunny.obj", bunny,
                 error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return "";
  }
  const TriangleMesh big = pn_subdivided(bunny, k);
  const std::string path =
      (dir / ("bunny-pn" + std::to_string(k) + "x" + std::to_string(k) + ".obj")).string();
  return write_obj(path, big) ? path : "";
}

void print_row(const std::string& mesh, const nlohmann::json& r, double peak_mb, double bare) {
  const nlohmann::json& s = r["stage_seconds"];
  const nlohmann::json& gi = r["geometry_image"];
  const nlohmann::json& g = gi["seconds"];
  const bool proxy = gi["proxy"].is_object() && gi["proxy"].value("used", false);
  const double floor = g["parameterize"].get<double>() + bare;
  const double whole = r["seconds"].get<double>();
  std::printf(
      "%-22s %8zu %7s %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f %6.2f | %6.2f "
      "%6.2f %6.2f %5.2f | %6.0f | %7.4f\n",
      mesh.c_str(), r["topology"]["faces"].get<size_t>(),
      proxy ? std::to_string(gi["proxy"]["faces"].get<size_t>() / 1000).append("K").c_str() : "-",
      s["mesh"].get<double>(), g["proxy"].get<double>(), g["repair"].get<double>(),
      g["parameterize"].get<double>(), g["measure"].get<double>(), s["image"].get<double>(),
      s["image_write"].get<double>(), s["field"].get<double>(), s["field_write"].get<double>(),
      s["verify"].get<double>(), whole, floor, whole / floor,
      (g["measure"].get<double>() + s["verify"].get<double>()) / whole, peak_mb,
      gi["reconstruction_error"]["mesh_to_image"]["mean_percent"].get<double>());
}

}  // namespace

int main(int argc, char** argv) {
  const BenchFolder folder("gfield_bench_asset_build");
  std::vector<std::string> meshes(argv + 1, argv + argc);
  if (meshes.empty()) {
    for (const char* file : {"spot.obj", "homer.obj", "stanford-bunny.obj"})
      meshes.push_back(std::string(gfield::build_paths::mesh_dir()) + "/" + file);
    for (int k : {3, 6})
      meshes.push_back(subdivided_bunny(folder.path, k));
  }
  std::printf("gfield build (defaults), one build each; seconds\n");
  std::printf(
      "%-22s %8s %7s %6s %6s %6s %6s %6s %6s %6s %6s %6s %6s | %6s %6s %6s %5s | %6s | "
      "%7s\n",
      "mesh", "faces", "proxy", "read", "simpl", "repair", "param", "measure", "image", "i.write",
      "field", "f.write", "verify", "whole", "floor", "/floor", "m+v", "MB", "m2i[%]");
  for (const std::string& mesh : meshes) {
    if (mesh.empty())
      continue;
    const std::string name = (folder.path / std::filesystem::path(mesh).stem()).string() + "-asset";
    nlohmann::json report;
    double peak_mb = 0.0;
    if (!run_build(mesh, name, {}, report, peak_mb))
      continue;
    const double bare =
        bare_cast_seconds(name, report["geometry_field"]["samples_per_side"].get<int>());
    print_row(std::filesystem::path(mesh).stem().string(), report, peak_mb, bare);
  }
  std::printf(
      "read: the mesh file; simpl: the proxy's simplification and projection BVH (meshes above "
      "--proxy-above faces); repair, param(eterisation), measure(ment): the image's stages (image: "
      "all of them, rasterisation included); i.write, f.write: the EXR (and OBJ) writes; field: "
      "BVH and casts; verify: the report's accuracy (--verify-rays rays per family).\n"
      "floor: the parameterisation the build did plus the bare first-hit cast of the field's "
      "rays on the mesh the field was cast on; /floor: whole / floor; m+v: measurement and "
      "verification's share of the whole; MB: peak resident memory of the build; m2i: the "
      "image's mean mesh -> image distance, percent of the diagonal.\n");
  return 0;
}
