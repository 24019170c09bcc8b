// The proxy route (`--proxy-above`, default 200,000 faces) across mesh families, in one run:
// whole `gfield build` runs (defaults) of flat-faced meshes (bundled meshes midpoint-subdivided:
// CAD parts, a modeller's output, the scanned bunny refined without smoothing), smooth ones (the
// bunny split on its PN patches, as a scan of it would be), and bundled meshes pushed through a
// proxy of half their faces; beside each, the same mesh built without a proxy (where that takes
// under a minute) and the original it was refined from. The columns the proxy's acceptance bound
// (an automatic size's mean mesh -> image distance within kProxyErrorFactor times the target)
// and the face limit (kMaxFaces) are judged by: route, mean mesh -> image distance, the refined
// lookup's box- and view-ray agreement with exact casts, seconds and peak memory.
// Usage: bench_proxy_families [--largest] (--largest adds the bunny midpoint-subdivided to 4.4M
// faces: about 25 s and 1 GB more).

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/build_runs.hpp"
#include "bench/example_scenes.hpp"
#include "bench/pn_subdivision.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/midpoint_subdivision.hpp"

namespace {

using namespace gfield;

/// One mesh of the table: a bundled mesh refined `levels` times by midpoints, or split k x k on
/// its PN patches (pn > 0), or as it is with a proxy of half its faces (proxy_half).
struct FamilyMesh {
  const char* family;
  const char* bundled;
  int levels = 0;
  int pn = 0;
  bool proxy_half = false;
};

struct BuildFigures {
  bool ok = false;
  size_t faces = 0;
  std::string route;
  size_t flips = 0;
  double mean = 0.0, box = 0.0, view = 0.0, seconds = 0.0, mb = 0.0;
};

BuildFigures build(const std::string& mesh, const std::string& name,
                   const std::vector<std::string>& options) {
  BuildFigures f;
  nlohmann::json r;
  if (!run_build(mesh, name, options, r, f.mb))
    return f;
  const nlohmann::json& gi = r["geometry_image"];
  const nlohmann::json& proxy = gi["proxy"];
  f.faces = r["topology"]["faces"].get<size_t>();
  if (proxy.is_object() && proxy["used"].get<bool>())
    f.route = "proxy " + std::to_string(proxy["faces"].get<size_t>() / 1000) + "K";
  else
    f.route = proxy.is_object() ? "full (proxy rejected)" : "full";
  f.flips = proxy.is_object() ? proxy.value("flat_flips", size_t(0)) : 0;
  f.mean = gi["reconstruction_error"]["mesh_to_image"]["mean_percent"].get<double>();
  const nlohmann::json& rays = r["accuracy"]["references"][0];
  f.box = 100.0 * rays["box_rays"]["refined"]["hit_agreement"].get<double>();
  f.view = 100.0 * rays["view_rays"]["refined"]["hit_agreement"].get<double>();
  f.seconds = r["seconds"].get<double>();
  f.ok = true;
  return f;
}

void print_row(const std::string& mesh, const char* family, const BuildFigures& f,
               const BuildFigures& full, const BuildFigures& original) {
  char full_figures[64] = "- | - | -", original_box[16] = "-";
  if (full.ok)
    std::snprintf(full_figures, sizeof(full_figures), "%.4f | %.1f | %.2f", full.mean, full.seconds,
                  full.mb / 1024.0);
  if (original.ok)
    std::snprintf(original_box, sizeof(original_box), "%.2f", original.box);
  std::printf("| %s | %s | %zu | %s | %zu | %.4f | %.2f | %.2f | %s | %.1f | %.2f | %s |\n",
              mesh.c_str(), family, f.faces, f.route.c_str(), f.flips, f.mean, f.box, f.view,
              original_box, f.seconds, f.mb / 1024.0, full_figures);
}

}  // namespace

int main(int argc, char** argv) {
  const bool largest = argc > 1 && std::strcmp(argv[1], "--largest") == 0;
  const BenchFolder folder("gfield_bench_proxy_families");
  std::vector<FamilyMesh> meshes = {{"flat CAD", "fandisk.obj", 2},
                                    {"flat CAD", "rocker-arm.obj", 2},
                                    {"flat model", "cow.obj", 3},
                                    {"flat model", "homer.obj", 3},
                                    {"flat model", "teapot.obj", 3},
                                    {"flat scan", "stanford-bunny.obj", 1},
                                    {"flat scan", "stanford-bunny.obj", 2},
                                    {"smooth scan", "stanford-bunny.obj", 0, 2},
                                    {"smooth scan", "stanford-bunny.obj", 0, 4},
                                    {"bundled", "stanford-bunny.obj", 0, 0, true},
                                    {"bundled", "homer.obj", 0, 0, true},
                                    {"bundled", "rocker-arm.obj", 0, 0, true}};
  if (largest)
    meshes.push_back({"flat scan", "stanford-bunny.obj", 3});
  std::printf(
      "gfield build (defaults) of each mesh; full: the same mesh with --proxy-above 0 (meshes "
      "under 400K faces); original: the bundled mesh it was refined from\n\n"
      "| mesh | family | faces | route | flips | mean mesh -> image [%%] | box rays [%%] | view "
      "rays [%%] | original's box rays [%%] | seconds | peak GB | full: mean [%%] | full: seconds "
      "| full: peak GB |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const FamilyMesh& m : meshes) {
    const std::string source = std::string(gfield::build_paths::mesh_dir()) + "/" + m.bundled;
    TriangleMesh mesh;
    std::string error;
    if (!load_mesh(source, mesh, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    std::string stem = std::filesystem::path(m.bundled).stem().string();
    if (m.levels > 0) {
      mesh = test::midpoint_subdivided(mesh, m.levels);
      stem += " x" + std::to_string(1 << (2 * m.levels));
    } else if (m.pn > 0) {
      mesh = pn_subdivided(mesh, m.pn);
      stem += " PN " + std::to_string(m.pn) + "x" + std::to_string(m.pn);
    }
    const std::string name = (folder.path / "asset").string();
    const std::string path = (folder.path / "mesh.obj").string();
    if (!write_obj(path, mesh)) {
      std::fprintf(stderr, "cannot write %s\n", path.c_str());
      return 1;
    }
    std::vector<std::string> options;
    if (m.proxy_half)
      options = {"--proxy-above", std::to_string(mesh.triangles.size() - 1)};
    const BuildFigures figures = build(path, name, options);
    if (!figures.ok)
      return 1;
    const BuildFigures full = mesh.triangles.size() < 400'000
                                  ? build(path, name, {"--proxy-above", "0"})
                                  : BuildFigures();
    const BuildFigures original = m.proxy_half ? BuildFigures() : build(source, name, {});
    print_row(stem, m.family, figures, full, original);
  }
  std::printf(
      "\nflips: edges of the proxy flipped where it is flat (preprocess/flat_flips.hpp); box and "
      "view rays: the refined lookup's hit/miss agreement with exact casts (the build's report, "
      "10,000 rays per family); seconds: the whole build; peak GB: its resident memory.\n");
  return 0;
}
