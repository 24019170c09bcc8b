// The geometry field's cost against the mesh's size, beside the BVH's: one mesh at growing face
// counts (spot 5.9K, the Stanford bunny 69K, the bunny split on its PN patches 2 x 2 into 278K
// and 4 x 4 into 1.1M faces, each scaled into spot's box), placed as the glass of the
// davis-wyman-color-chart scene and, in a copy of it, as a mirror. Per mesh and scene: ms per
// frame, and of its tracing pass alone, with the mesh looked up in its geometry field (refined)
// and traced exactly through its BVH (both rasterise the mesh into the G-buffer), the PSNR of each
// against the Embree reference tracer's picture (1 spp, same depth), the GPU bytes of each, and the
// work per lookup or traversal (counted on the GPU); and
// --intersect auto's time against the faster of the two, with the route it took. Then, per mesh,
// rays that hit it and rays that miss it apart (view rays, mirror reflections off its surface,
// refractions into it): the time and work per ray of the field lookup and of the BVH walk, and
// the GPU's agreement with the exact cast (bench/ray_work.hpp). Prints markdown.
// Assets are built with `gfield build` (its defaults) into a temporary folder.
//
// Usage: bench_runtime_complexity [--frames F] [--depth D] [SIZE]   (default 1 frame per round,
// depth 4, 256)

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/pn_subdivision.hpp"
#include "bench/ray_work.hpp"
#include "example_scenes.hpp"
#include "gl_bench_setup.hpp"
#include "preprocess/reference_tracer.hpp"
#include "runtime/shader_program.hpp"
#include "runtime_runs.hpp"
#include "test_support/build_paths.hpp"

namespace fs = std::filesystem;
using namespace gfield;

namespace {

/// Rays per family of the per-ray table, at most (each split into hits and misses), and the
/// fewest rays a row is timed for (a pass over fewer is too short to time).
constexpr size_t kRaysPerFamily = 16384;
constexpr size_t kFewestRaysTimed = 256;
/// Rounds of the field, the BVH and auto in turn, each of --frames timed frames (run_interleaved).
constexpr int kRounds = 3;

/// `mesh` moved and scaled so that its box has `target`'s centre and diagonal.
TriangleMesh fitted(TriangleMesh mesh, const TriangleMesh& target) {
  const auto box = [](const TriangleMesh& m, glm::dvec3& lo, glm::dvec3& hi) {
    lo = glm::dvec3(1e300);
    hi = glm::dvec3(-1e300);
    for (const glm::dvec3& p : m.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  };
  glm::dvec3 lo, hi, target_lo, target_hi;
  box(mesh, lo, hi);
  box(target, target_lo, target_hi);
  const double scale = glm::length(target_hi - target_lo) / glm::length(hi - lo);
  for (glm::dvec3& p : mesh.positions)
    p = (target_lo + target_hi) / 2.0 + scale * (p - (lo + hi) / 2.0);
  return mesh;
}

/// One mesh of the series: its name, faces and asset (DIR/NAME).
struct SeriesMesh {
  std::string name;
  size_t faces = 0;
  std::string file;
  std::string asset;
};

/// The four meshes, written into `dir` and built; false (with a message) on failure.
bool make_series(const fs::path& dir, std::vector<SeriesMesh>& series) {
  TriangleMesh spot, bunny;
  std::string error;
  if (!load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/spot.obj", spot, error) ||
      !load_mesh(std::string(gfield::build_paths::mesh_dir()) + "/stanford-bunny.obj", bunny,
                 error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return false;
  }
  const TriangleMesh fitted_bunny = fitted(bunny, spot);
  const std::pair<std::string, TriangleMesh> meshes[] = {
      {"spot", spot},
      {"bunny", fitted_bunny},
      {"bunny-pn2x2", pn_subdivided(fitted_bunny, 2)},
      {"bunny-pn4x4", pn_subdivided(fitted_bunny, 4)}};
  for (const auto& [name, mesh] : meshes) {
    SeriesMesh m{name, mesh.triangles.size(), (dir / (name + ".obj")).string(),
                 (dir / name).string()};
    Stopwatch watch;
    if (!write_obj(m.file, mesh) ||
        !run_gfield_cli("build \"" + m.file + "\" -o \"" + m.asset + "\" --verify-rays 0"))
      return false;
    std::printf("built %s (%zu faces) in %.1f s\n", name.c_str(), m.faces, watch.seconds());
    series.push_back(m);
  }
  return true;
}

/// data/scenes/davis-wyman-color-chart.json with its glass object's mesh replaced by `m`, of
/// material `material` (the scene's dielectric, or a mirror); the scene file's path.
std::string series_scene(const SeriesMesh& m, bool mirror, const fs::path& dir) {
  const fs::path source =
      fs::path(gfield::build_paths::data_dir()) / "scenes/davis-wyman-color-chart.json";
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(source));
  for (auto& object : scene["objects"]) {
    if (object["shape"] != "mesh")
      continue;
    object["file"] = m.file;
    object["gimage"] = m.asset + ".gimage.exr";
    object["gfield"] = m.asset + ".gfield.exr";
    if (mirror)
      object["material"] = {{"type", "mirror"}};
  }
  const std::string out = (dir / (m.name + (mirror ? "-mirror" : "-glass") + ".json")).string();
  std::ofstream(out) << scene.dump(2);
  return out;
}

/// The rows of one mesh in one scene: field (refined) and BVH.
void bench_scene(const SeriesMesh& m, const std::string& file, const char* kind, int size,
                 int depth, int frames) {
  Scene scene;
  GpuScene gpu;
  GeometryFieldMethod method;
  ReferenceTracer tracer;
  std::string error;
  if (!load_scene(file, scene, error, OutsidePaths::kAllowed) || !gpu.load(scene, error) ||
      !method.load(gpu, default_shader_dir(), error) || !tracer.build(scene, error)) {
    std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
    return;
  }
  RenderOptions options;
  options.width = options.height = size;
  options.samples_per_pixel = 1;
  options.max_depth = depth;
  options.jitter = false;
  const Image reference = clamped_to_display(tracer.render(options));
  method.settings().max_depth = depth;
  method.settings().mode = LookupMode::kRefined;
  // One pass for every route and round: --pass auto's trial restarts whenever the route changes
  // and may settle on another pass each round. The fragment pass is the BVH's faster on llvmpipe
  // and the field's equal (bench_runtime_field).
  method.settings().pass = TracePass::kFragment;
  const MeshIntersection routes[] = {MeshIntersection::kField, MeshIntersection::kBvh,
                                     MeshIntersection::kAuto};
  const std::vector<Run> runs =
      run_interleaved(method, scene, size, frames, kRounds, reference, 3,
                      [&](int k) { method.settings().intersect = routes[k]; });
  const Run &field = runs[0], &bvh = runs[1], &automatic = runs[2];
  const std::string status = method.status();
  const std::string route = status.substr(0, status.find('\n'));
  double field_mb = 0.0, bvh_mb = 0.0;
  asset_bytes(gpu, field_mb, bvh_mb);
  std::printf("| %s | %zu | %s | field | %s | %s | %.2f | %.1f | %s |\n", m.name.c_str(), m.faces,
              kind, range_text(field.wall).c_str(), range_text(field.tracing).c_str(), field.psnr,
              field_mb, work_line(field.per_sample).c_str());
  std::printf("| | | | BVH | %s | %s | %.2f | %.1f | %s |\n", range_text(bvh.wall).c_str(),
              range_text(bvh.tracing).c_str(), bvh.psnr, bvh_mb, work_line(bvh.per_sample).c_str());
  std::printf("| | | | field / BVH | %.2f | %.2f | %+.2f | | |\n", field.ms / bvh.ms,
              field.tracing.median / bvh.tracing.median, field.psnr - bvh.psnr);
  std::printf("| | | | auto / the faster | %.2f | %.2f | %.2f | | %s |\n",
              automatic.ms / std::min(field.ms, bvh.ms),
              automatic.tracing.median / std::min(field.tracing.median, bvh.tracing.median),
              automatic.psnr, route.substr(std::min(route.size(), route.find("by"))).c_str());
  std::fflush(stdout);
}

/// Work per ray of `work` over `rays` rays: "F + I fetches, N Newton".
std::string work_text(const LookupWork& work, size_t rays) {
  const auto per = [&](int k) { return double(work.counts[size_t(k)]) / double(rays); };
  char text[96];
  std::snprintf(text, sizeof(text), "%.1f + %.1f fetches, %.1f Newton",
                per(gpu::WORK_FIELD_FETCHES), per(gpu::WORK_IMAGE_FETCHES),
                per(gpu::WORK_NEWTON_STEPS));
  return text;
}

/// The per-ray rows of mesh `m` (its glass scene's assets): each family's rays that hit and rays
/// that miss, their work counted on the CPU, field against BVH, and the GPU lookup's answers.
void bench_rays(const SeriesMesh& m, const std::string& scene_file, size_t count) {
  Scene scene;
  TriangleMesh mesh;
  GeometryImage image;
  GeometryField field;
  EmbreeMesh embree;
  FieldLookup lookup;
  GpuAssets assets;
  AssetNeeds needs;
  needs.fields = needs.bvhs = true;
  std::string error;
  if (!load_scene(scene_file, scene, error, OutsidePaths::kAllowed) ||
      !load_mesh(m.file, mesh, error) ||
      !load_geometry_image(m.asset + ".gimage.exr", image, error) ||
      !load_geometry_field(m.asset + ".gfield.exr", field, error) || !embree.build(mesh, error) ||
      !assets.require(scene, needs, error)) {
    std::fprintf(stderr, "%s: %s\n", m.name.c_str(), error.c_str());
    return;
  }
  const GeometryField stored = quantized_field(field, needs.field_bits);  // what the GPU reads
  if (!make_field_lookup(stored, image, lookup, error)) {
    std::fprintf(stderr, "%s: %s\n", m.name.c_str(), error.c_str());
    return;
  }
  const std::vector<glm::vec3> positions(mesh.positions.begin(), mesh.positions.end());
  const MeshBvh bvh = build_mesh_bvh(positions, mesh.triangles);
  const Box& box = assets.asset(0).box;
  for (const RayFamily& family :
       ray_families(embree, mesh, box, surface_offsets(image, box), count)) {
    for (const bool exact : {true, false}) {
      const RaySet& set = exact ? family.hits : family.misses;
      if (set.rays.size() < kFewestRaysTimed) {
        std::printf("| %s | %zu | %s | %s | %zu | | | | | too few to time | |\n", m.name.c_str(),
                    m.faces, family.name, exact ? "hit" : "miss", set.rays.size());
        continue;
      }
      SetWork w;
      if (!work_of_set(assets, lookup, bvh, positions, mesh, set, family.self_t_min, exact, w))
        continue;
      std::printf("| %s | %zu | %s | %s | %zu | %.0f | %.0f | %.2f | %.2f / %.2f | %s | %.1f |\n",
                  m.name.c_str(), m.faces, family.name, exact ? "hit" : "miss", set.rays.size(),
                  w.field_ns, w.bvh_ns, w.field_ns / w.bvh_ns, w.agree, w.bvh_agree,
                  work_text(w.field, set.rays.size()).c_str(), w.bvh_nodes);
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  int depth = 4, frames = 1, size = 256;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool option = (arg == "--depth" || arg == "--frames") && i + 1 < argc;
    const int value = std::atoi(option ? argv[++i] : argv[i]);
    (arg == "--depth" ? depth : arg == "--frames" ? frames : size) = value;
    if (value < 1 || (!option && arg[0] == '-')) {
      std::fprintf(stderr, "usage: bench_runtime_complexity [--frames F] [--depth D] [SIZE]\n");
      return 2;
    }
  }
  const BenchFolder folder("gfield_bench_runtime_complexity");
  std::vector<SeriesMesh> series;
  if (!make_series(folder.path, series))
    return 2;
  auto context = create_bench_context();
  if (!context)
    return kExitNoOpenGL;
  std::printf(
      "\n%dx%d, depth %d, fragment pass, %d timed frames in %d rounds of field, BVH and auto in "
      "turn; PSNR against the reference tracer (1 spp)\n\n",
      size, size, depth, frames * kRounds, kRounds);
  std::printf(
      "| mesh | faces | scene | route | ms/frame (min-max) | tracing ms (min-max) | PSNR dB | GPU "
      "MB | work |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (const SeriesMesh& m : series)
    for (const bool mirror : {false, true})
      bench_scene(m, series_scene(m, mirror, folder.path), mirror ? "mirror" : "glass", size, depth,
                  frames);
  std::printf("\n%s\n", kFrameTimeNote);
  std::printf(
      "tracing ms: the tracing pass alone (GPU time), the frame less its G-buffer; both routes "
      "rasterise the same mesh into the G-buffer, which grows with its faces\n");
  std::printf(
      "\nPer ray, rays that hit the mesh and rays that miss it apart (Embree's exact cast), "
      "%zu rays per family at most: ns per ray of each route in the probe pass (one "
      "fragment per ray, the median of 5 timed passes, each from a finished GPU to its "
      "end), the answers that agree with the exact cast (field / BVH), and the work of the "
      "field lookup and of the BVH walk, counted on the CPU by the code the shaders "
      "run\n\n",
      kRaysPerFamily);
  std::printf(
      "| mesh | faces | rays | exact | count | field ns | BVH ns | field / BVH | agree %% "
      "field / BVH | field work | BVH nodes |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const SeriesMesh& m : series)
    bench_rays(m, series_scene(m, false, folder.path), kRaysPerFamily);
  return 0;
}
