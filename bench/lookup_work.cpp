// What a CPU geometry-field lookup costs and how often it is right, per ray family and mode: the
// work counters the shaders count (field and image texel fetches, Newton steps, gf_trace calls;
// shaders/lib/field_lookup.glsl is the same code on both sides) per ray, beside the hit/miss
// agreement with exact Embree casts and the position error. The families are those the runtime
// casts: box-face segments, view rays, mirror reflections off the surface and refractions into
// the solid (glass), the last two looked up as rays leaving the surface. Fields at 8 bits, as the
// GPU stores them. Usage: bench_lookup_work [rays] [mesh ...] (20000 rays; spot and the bunny).

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/bench_assets.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/gpu_storage.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/verify.hpp"

namespace {

using namespace gfield;

/// One family's rays: plain (first hits) or leaving the surface.
struct Family {
  const char* name;
  std::vector<Ray> rays;
  SurfaceRays leaving;
  bool is_leaving = false;
};

/// Work per ray of `family` in `mode`, one thread.
LookupWork count_work(const FieldLookup& lookup, const Family& family, LookupMode mode) {
  LookupWork work;
  FieldLookup counted = lookup;
  counted.work = &work;
  const SurfaceRays& s = family.leaving;
  for (size_t i = 0; i < family.rays.size(); ++i) {
    if (family.is_leaving) {
      lookup_first_hit_leaving(counted, s.rays[i], s.self_origins[i], s.self_t_min, s.facing[i],
                               mode);
    } else {
      lookup_first_hit(counted, family.rays[i], mode);
    }
  }
  return work;
}

bool report_mesh(const std::string& file, size_t count) {
  BenchAsset asset;
  if (!load_bench_asset(file, kAutoImageSize, asset)) {
    return false;
  }
  std::string error;
  EmbreeMesh embree;
  GeometryField field;
  if (!embree.build(asset.pm.mesh, error) ||
      !build_geometry_field(asset.pm, embree, asset.image, 24, field, error)) {
    std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
    return false;
  }
  field.source = asset.image.source;
  field = quantized_field(field, 8);
  FieldLookup lookup;
  if (!make_field_lookup(field, asset.image, lookup, error)) {
    std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
    return false;
  }
  const TriangleMesh& mesh = asset.pm.mesh;
  const SurfaceOffsets offsets = surface_offsets(asset.image, field.box);
  std::vector<Family> families;
  families.push_back({"box", random_box_rays(field.box, count, 1), {}, false});
  families.push_back({"view", random_view_rays(field.box, count, 2), {}, false});
  families.push_back(
      {"mirror", {}, mirror_surface_rays(embree, mesh, field.box, count, offsets, 4), true});
  families.push_back(
      {"glass", {}, glass_surface_rays(embree, mesh, field.box, count, offsets, 5), true});
  std::printf("\n%s: %d faces, image %d^2, N = 24, K = %d, 8 bits\n", asset.name.c_str(),
              int(mesh.triangles.size()), asset.image.size, field.layers);
  std::printf("%-7s %-8s %9s %9s %7s %7s %8s %8s %8s %8s\n", "family", "mode", "agree %",
              "pos med %", "exact", "answer", "field", "image", "Newton", "lookups");
  for (Family& family : families) {
    if (family.is_leaving) {
      family.rays = family.leaving.rays;
    }
    for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
      const AccuracyStats s =
          family.is_leaving ? verify_lookup(lookup, embree, mesh, family.leaving, mode)
                            : verify_lookup(lookup, embree, mesh, family.rays, mode, false, {});
      const LookupWork work = count_work(lookup, family, mode);
      const double rays = double(family.rays.size());
      std::printf("%-7s %-8s %9.3f %9.4f %7zu %7zu %8.1f %8.1f %8.2f %8.2f\n", family.name,
                  lookup_mode_name(mode), 100.0 * s.hit_agreement(), s.position_median,
                  s.exact_hits, s.answer_hits, double(work.counts[gpu::WORK_FIELD_FETCHES]) / rays,
                  double(work.counts[gpu::WORK_IMAGE_FETCHES]) / rays,
                  double(work.counts[gpu::WORK_NEWTON_STEPS]) / rays,
                  double(work.counts[gpu::WORK_LOOKUPS]) / rays);
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const size_t count = argc > 1 ? size_t(std::atol(argv[1])) : 20000;
  std::vector<std::string> files;
  for (int i = 2; i < argc; ++i) {
    files.push_back(argv[i]);
  }
  if (files.empty()) {
    files = {"spot.obj", "stanford-bunny.obj"};
  }
  std::printf("work and accuracy per ray of CPU lookups, %zu rays per family\n", count);
  for (const std::string& file : files) {
    if (!report_mesh(file, count)) {
      return 1;
    }
  }
  return 0;
}
