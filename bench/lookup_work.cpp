// What a CPU geometry-field lookup costs and how often it is right, per ray family and mode: the
// work counters the shaders count (field and image texel fetches, Newton steps, gf_trace calls;
// shaders/lib/field_lookup.glsl is the same code on both sides) per ray, beside the hit/miss
// agreement with exact Embree casts and the position error (median and 99th percentile, percent
// of the box diagonal), and the work of the rays whose exact cast hits and of those whose exact
// cast misses, apart (fetches: field + image). The families are those the runtime casts:
// box-face segments, view rays, and rays leaving the surface: mirror reflections, shadow rays (any
// hit will do, as the runtime looks them up), refractions into the solid (glass) and their next
// step inside it (inside: out into the open or totally reflected); that next step from the hits
// the field found rather than the exact ones (inside*: the runtime's rays after the first
// refraction; their exact casts ignore no triangle, so their agreement is approximate); and, in
// refined mode, the shadow rays' peers: looked up on either side of the surface (shadow-e) and on
// their side alone (shadow-s). Fields at 8 bits, as the GPU stores them. Usage:
// bench_lookup_work [rays] [mesh ...] (20000 rays; spot and the bunny).

#include <algorithm>
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

/// One family's rays: plain (first hits) or leaving the surface; `refined_only`: a peer of a
/// family's refined lookup, printed in refined mode alone.
struct Family {
  const char* name;
  std::vector<Ray> rays;
  SurfaceRays leaving;
  bool is_leaving = false;
  bool refined_only = false;
};

/// The shadow rays' peers: looked up on either side of the surface (facing 0), and on their side
/// alone (no second lookup where the first doubts).
std::vector<Family> shadow_peers(const SurfaceRays& shadow) {
  SurfaceRays either = shadow;
  either.any_hit = false;
  std::fill(either.facing.begin(), either.facing.end(), 0.0f);
  SurfaceRays side = shadow;
  side.any_hit = false;
  return {{"shadow-e", {}, either, true, true}, {"shadow-s", {}, side, true, true}};
}

/// The glass path's next step as the runtime casts it from a hit the field found (not an exact
/// one): each ray of `into` looked up (refined), and at its hit refracted out of the solid (eta =
/// ior) or, where that is total, reflected, about the geometry image's normal; moved off the
/// image's surface by offsets.path for the ray and its lookup alike (shaders/lib/scene.glsl,
/// object_epsilon of a point found by a lookup). The exact casts of these rays ignore no triangle.
SurfaceRays rays_leaving_field_hits(const FieldLookup& lookup, const SurfaceRays& into,
                                    SurfaceOffsets offsets, float ior) {
  SurfaceRays out;
  out.self_t_min = 2.0f * offsets.path;
  for (size_t i = 0; i < into.rays.size(); ++i) {
    const FieldHit h =
        lookup_first_hit_leaving(lookup, into.rays[i], into.self_origins[i], into.self_t_min,
                                 into.facing[i], LookupMode::kRefined);
    if (!h.hit) {
      continue;
    }
    const glm::vec3 d = glm::normalize(into.rays[i].direction);
    glm::vec3 n = glm::dot(d, h.normal) < 0.0f ? h.normal : -h.normal;
    glm::vec3 r = glm::refract(d, n, ior);
    glm::vec3 g = -n;  // through the surface
    if (glm::dot(r, r) == 0.0f) {
      r = glm::reflect(d, n);
      g = n;
    }
    out.rays.push_back(
        {h.position + offsets.path * g, glm::normalize(r), 2.0f * offsets.path, gpu::GF_FAR});
    out.self_origins.push_back(h.position + offsets.path * g);
    out.facing.push_back(glm::dot(h.normal, g) >= 0.0f ? 1.0f : -1.0f);
    out.triangles.push_back(-1);
  }
  return out;
}

/// Work of `family`'s rays in `mode`, one thread: rays whose exact cast hits the mesh, and rays
/// whose exact cast misses it, apart.
struct FamilyWork {
  LookupWork hits;
  LookupWork misses;
  size_t hit_rays = 0;
};

FamilyWork count_work(const FieldLookup& lookup, const EmbreeMesh& embree, const Family& family,
                      LookupMode mode) {
  FamilyWork work;
  const SurfaceRays& s = family.leaving;
  for (size_t i = 0; i < family.rays.size(); ++i) {
    const Ray& ray = family.rays[i];
    const int ignored = family.is_leaving ? s.triangles[i] : -1;
    const bool exact =
        intersect(embree, ray.origin, ray.direction, ray.t_min, ray.t_max, ignored).hit;
    FieldLookup counted = lookup;
    counted.work = exact ? &work.hits : &work.misses;
    work.hit_rays += exact ? 1 : 0;
    if (family.is_leaving) {
      lookup_first_hit_leaving(counted, ray, s.self_origins[i], s.self_t_min, s.facing[i], mode,
                               s.any_hit);
    } else {
      lookup_first_hit(counted, ray, mode);
    }
  }
  return work;
}

/// Counter `kind` per ray of the `rays` rays that `work` counted; 0 for no rays.
double per_ray(const LookupWork& work, int kind, size_t rays) {
  return rays == 0 ? 0.0 : double(work.counts[kind]) / double(rays);
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
      {"shadow", {}, shadow_surface_rays(embree, mesh, field.box, count, offsets, 7), true});
  families.push_back(
      {"glass", {}, glass_surface_rays(embree, mesh, field.box, count, offsets, 5), true});
  families.push_back(
      {"inside", {}, glass_inside_rays(embree, mesh, field.box, count, offsets, 6), true});
  families.push_back(
      {"inside*", {}, rays_leaving_field_hits(lookup, families[4].leaving, offsets, 1.5f), true});
  for (const Family& peer : shadow_peers(families[3].leaving)) {
    families.push_back(peer);
  }
  std::printf("\n%s: %d faces, image %d^2, N = 24, K = %d, 8 bits\n", asset.name.c_str(),
              int(mesh.triangles.size()), asset.image.size, field.layers);
  std::printf("%-8s %-8s %9s %9s %9s %7s %7s %8s %8s %8s %8s | %8s %8s | %8s %8s\n", "family",
              "mode", "agree %", "pos med %", "pos p99 %", "exact", "answer", "field", "image",
              "Newton", "lookups", "hit f+i", "hit N", "miss f+i", "miss N");
  for (Family& family : families) {
    if (family.is_leaving) {
      family.rays = family.leaving.rays;
    }
    for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
      if (family.refined_only && mode != LookupMode::kRefined) {
        continue;
      }
      const AccuracyStats s =
          family.is_leaving ? verify_lookup(lookup, embree, mesh, family.leaving, mode)
                            : verify_lookup(lookup, embree, mesh, family.rays, mode, false, {});
      const FamilyWork w = count_work(lookup, embree, family, mode);
      LookupWork all = w.hits;
      for (int k = 0; k < gpu::WORK_COUNT; ++k) {
        all.counts[k] += w.misses.counts[k];
      }
      const size_t rays = family.rays.size();
      const size_t miss_rays = rays - w.hit_rays;
      auto fetches = [](const LookupWork& work, size_t n) {
        return per_ray(work, gpu::WORK_FIELD_FETCHES, n) +
               per_ray(work, gpu::WORK_IMAGE_FETCHES, n);
      };
      std::printf(
          "%-8s %-8s %9.3f %9.4f %9.4f %7zu %7zu %8.1f %8.1f %8.2f %8.2f | %8.1f %8.2f | %8.1f "
          "%8.2f\n",
          family.name, lookup_mode_name(mode), 100.0 * s.hit_agreement(), s.position_median,
          s.position_p99, s.exact_hits, s.answer_hits, per_ray(all, gpu::WORK_FIELD_FETCHES, rays),
          per_ray(all, gpu::WORK_IMAGE_FETCHES, rays), per_ray(all, gpu::WORK_NEWTON_STEPS, rays),
          per_ray(all, gpu::WORK_LOOKUPS, rays), fetches(w.hits, w.hit_rays),
          per_ray(w.hits, gpu::WORK_NEWTON_STEPS, w.hit_rays), fetches(w.misses, miss_rays),
          per_ray(w.misses, gpu::WORK_NEWTON_STEPS, miss_rays));
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
