// CPU geometry-field lookups per mode vs Embree's rtcIntersect1 on the same rays (one thread
// each, so the figures are per core): random box-face rays, then rays leaving the surface
// (random_surface_rays) with the first layer only and with all K layers of the default field (K
// chosen), against rtcIntersect1 past the origin's triangle. Usage: bench_field_lookup [rays] [N]
// (100000 rays, N = 24, meshes spot, homer and the bunny at 512^2).

#include <cstdio>
#include <cstdlib>

#include "bench/bench_assets.hpp"
#include "gfield/field_lookup.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/field_build.hpp"
#include "preprocess/verify.hpp"

int main(int argc, char** argv) {
  using namespace gfield;
  const size_t count = argc > 1 ? size_t(std::atol(argv[1])) : 100000;
  const int n = argc > 2 ? std::atoi(argv[2]) : 24;
  std::printf("lookups of %zu random box-face rays, N = %d, one thread\n", count, n);
  std::printf("%-16s %-14s %12s %10s %12s\n", "mesh", "method", "Mrays/s", "ns/ray", "vs embree");
  for (const char* file : {"spot.obj", "homer.obj", "stanford-bunny.obj"}) {
    BenchAsset asset;
    if (!load_bench_asset(file, 512, asset)) {
      return 1;
    }
    std::string error;
    EmbreeMesh embree;
    GeometryField field;
    if (!embree.build(asset.pm.mesh, error) ||
        !build_geometry_field(asset.pm, embree, asset.image, n, field, error)) {
      std::fprintf(stderr, "%s: %s\n", file, error.c_str());
      return 1;
    }
    field.source = asset.image.source;
    FieldLookup lookup;
    if (!make_field_lookup(field, asset.image, lookup, error)) {
      std::fprintf(stderr, "%s: %s\n", file, error.c_str());
      return 1;
    }
    const std::vector<Ray> box_rays = random_box_rays(field.box, count, 1);
    const auto time = [&](const auto& cast, const std::vector<Ray>& rays) {
      double best = 1e30;
      size_t hits = 0;
      for (int r = 0; r < 3; ++r) {
        hits = 0;
        Stopwatch watch;
        for (size_t i = 0; i < rays.size(); ++i) {
          hits += size_t(cast(rays[i], i));
        }
        best = std::min(best, watch.seconds());
      }
      return std::make_pair(best, hits);
    };
    const auto [embree_seconds, embree_hits] = time(
        [&](const Ray& ray, size_t) {
          return intersect(embree, ray.origin, ray.direction, ray.t_min, ray.t_max).hit;
        },
        box_rays);
    std::printf("%-16s %-14s %12.2f %10.0f %12s\n", asset.name.c_str(), "rtcIntersect1",
                double(count) / embree_seconds / 1e6, 1e9 * embree_seconds / double(count), "1.00");
    for (LookupMode mode : {LookupMode::kNearest, LookupMode::kLinear, LookupMode::kRefined}) {
      const auto [seconds, hits] =
          time([&](const Ray& ray, size_t) { return lookup_first_hit(lookup, ray, mode).hit; },
               box_rays);
      char ratio[32];
      std::snprintf(ratio, sizeof(ratio), "%.2f", embree_seconds / seconds);
      std::printf("%-16s %-14s %12.2f %10.0f %12s\n", "", lookup_mode_name(mode),
                  double(count) / seconds / 1e6, 1e9 * seconds / double(count), ratio);
    }
    const SurfaceRays surface =
        random_surface_rays(asset.pm.mesh, count, surface_offsets(asset.image, field.box), 2);
    const auto [surface_seconds, surface_hits] = time(
        [&](const Ray& ray, size_t i) {
          return intersect(embree, ray.origin, ray.direction, 0.0f, ray.t_max, surface.triangles[i])
              .hit;
        },
        surface.rays);
    (void)surface_hits;
    std::printf("%-16s %-14s %12.2f %10.0f %12s\n", "surface rays", "rtcIntersect1",
                double(count) / surface_seconds / 1e6, 1e9 * surface_seconds / double(count),
                "1.00");
    for (int layers : {1, field.layers}) {
      lookup.layers = layers;
      const auto [seconds, hits] = time(
          [&](const Ray& ray, size_t i) {
            return lookup_first_hit_leaving(lookup, ray, surface.self_origins[i],
                                            surface.self_t_min, 1.0f, LookupMode::kRefined)
                .hit;
          },
          surface.rays);
      char label[32], ratio[32];
      std::snprintf(label, sizeof(label), "refined K=%d", layers);
      std::snprintf(ratio, sizeof(ratio), "%.2f", surface_seconds / seconds);
      std::printf("%-16s %-14s %12.2f %10.0f %12s\n", "", label, double(count) / seconds / 1e6,
                  1e9 * seconds / double(count), ratio);
    }
  }
  std::printf("vs embree: lookup rays/s divided by rtcIntersect1 rays/s (> 1: faster)\n");
  return 0;
}
