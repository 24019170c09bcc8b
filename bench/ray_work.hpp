#pragma once
// What one ray costs, rays that hit the mesh and rays that miss it apart (by Embree's exact
// cast), the field lookup (refined) against the BVH, for bench_runtime_complexity: each route's
// time per ray in the probe pass (runtime/field_probe.hpp: one fragment per ray, the rays of one
// kind together, so that no group mixes kinds), the GPU lookup's answers against the exact cast,
// and the work of each ray counted on the CPU by the code the shaders run (the lookup:
// shaders/lib/field_lookup.glsl; the walk: shaders/lib/bvh_trace.glsl).

#include <cstdio>
#include <string>
#include <vector>

#include "geometry/mesh_bvh.hpp"
#include "gfield/exr_io.hpp"
#include "gfield/gpu_storage.hpp"
#include "preprocess/verify_rays.hpp"
#include "runtime/field_probe.hpp"
#include "runtime/shader_program.hpp"

namespace gfield {

/// Rays of one kind: plain, or leaving the surface (`self`: per ray, the origin of its own
/// lookup and its facing).
struct RaySet {
  std::vector<Ray> rays;
  std::vector<glm::vec4> self;
};

/// A family of rays the runtime casts at a mesh, split by the exact cast.
struct RayFamily {
  const char* name;
  RaySet hits, misses;
  float self_t_min = 0.0f;
};

/// Ray i of `all` into `hits` or `misses` by Embree's exact cast.
inline void split_by_exact_cast(const EmbreeMesh& embree, const SurfaceRays& all, bool leaving,
                                RayFamily& family) {
  for (size_t i = 0; i < all.rays.size(); ++i) {
    const Ray& r = all.rays[i];
    const int left = leaving ? all.triangles[i] : -1;
    RaySet& set = intersect(embree, r.origin, r.direction, r.t_min, r.t_max, left).hit
                      ? family.hits
                      : family.misses;
    set.rays.push_back(r);
    if (leaving)
      set.self.emplace_back(all.self_origins[i], all.facing[i]);
  }
}

/// The runtime's rays at a mesh: view rays from around its box, mirror reflections off its
/// surface and refractions into the solid (preprocess/verify_rays.hpp), `count` of each at most.
inline std::vector<RayFamily> ray_families(const EmbreeMesh& embree, const TriangleMesh& mesh,
                                           const Box& box, SurfaceOffsets offsets, size_t count) {
  std::vector<RayFamily> families(3);
  families[0].name = "view";
  SurfaceRays view;
  view.rays = random_view_rays(box, count, 1);
  split_by_exact_cast(embree, view, false, families[0]);
  families[1].name = "mirror";
  const SurfaceRays mirror = mirror_surface_rays(embree, mesh, box, count, offsets, 2);
  families[1].self_t_min = mirror.self_t_min;
  split_by_exact_cast(embree, mirror, true, families[1]);
  families[2].name = "glass";
  const SurfaceRays glass = glass_surface_rays(embree, mesh, box, count, offsets, 3);
  families[2].self_t_min = glass.self_t_min;
  split_by_exact_cast(embree, glass, true, families[2]);
  return families;
}

/// One set's figures: each route's ns per ray in the probe pass, the GPU's answers that agree
/// with the exact cast, and the work per ray counted on the CPU.
struct SetWork {
  double field_ns = 0.0, bvh_ns = 0.0;
  double agree = 0.0;      ///< the field's, percent
  double bvh_agree = 0.0;  ///< the BVH walk's (the rasterised mesh, float), percent
  LookupWork field;
  double bvh_nodes = 0.0;
};

/// The probe of `set` by `query`, 5 timed passes: its answers, and ns per ray in `ns`.
inline bool probe_set(const GpuAssets& assets, const RaySet& set, const ProbeQuery& query,
                      ProbeResult& result, double& ns) {
  std::string error;
  if (!probe_rays_gpu(assets, 0, set.rays, query, 5, default_shader_dir().string(), result,
                      error)) {
    std::fprintf(stderr, "probe: %s\n", error.c_str());
    return false;
  }
  ns = result.ms * 1e6 / double(set.rays.size());
  return true;
}

/// Times, counts and checks `set` (rays that all hit, `exact`, or all miss) both ways.
inline bool work_of_set(const GpuAssets& assets, const FieldLookup& lookup, const MeshBvh& bvh,
                        const std::vector<glm::vec3>& positions, const TriangleMesh& mesh,
                        const RaySet& set, float self_t_min, bool exact, SetWork& work) {
  ProbeQuery query;
  query.self = set.self;
  query.self_t_min = self_t_min;
  ProbeQuery walk;
  walk.bvh = true;
  ProbeResult gpu, walked;
  if (!probe_set(assets, set, query, gpu, work.field_ns) ||
      !probe_set(assets, set, walk, walked, work.bvh_ns))
    return false;
  FieldLookup counted = lookup;
  counted.work = &work.field;
  size_t agree = 0, walks_agree = 0, nodes = 0;
  for (size_t i = 0; i < set.rays.size(); ++i) {
    const Ray& r = set.rays[i];
    agree += (gpu.hits[i].x > 0.5f) == exact ? 1 : 0;
    walks_agree += (walked.hits[i].x > 0.5f) == exact ? 1 : 0;
    if (set.self.empty())
      lookup_first_hit(counted, r, LookupMode::kRefined);
    else
      lookup_first_hit_leaving(counted, r, glm::vec3(set.self[i]), self_t_min, set.self[i].w,
                               LookupMode::kRefined);
    nodes += size_t(
        trace_mesh_bvh(bvh, positions, mesh.triangles, r.origin, r.direction, r.t_min, r.t_max)
            .nodes_visited);
  }
  work.agree = 100.0 * double(agree) / double(set.rays.size());
  work.bvh_agree = 100.0 * double(walks_agree) / double(set.rays.size());
  work.bvh_nodes = double(nodes) / double(set.rays.size());
  return true;
}

}  // namespace gfield
