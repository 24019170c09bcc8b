#pragma once
// Mesh queries on the GPU for rays given by the caller (shaders/field_probe.frag): a
// geometry-field lookup or the exact hit through the mesh's BVH, one fragment per ray, rays in
// mesh coordinates: the GPU side of the CPU/GPU agreement checks of the lookup and of the BVH,
// and the per-ray times of bench_runtime_complexity (rays that hit and rays that miss, apart).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/field_lookup.hpp"
#include "runtime/gpu_assets.hpp"

namespace gfield {

/// How a probe meets the mesh: by a lookup in its field (`mode`, the first or the last hit), or
/// exactly through its BVH (`bvh`: the assets loaded with their BVHs). Rays leaving the surface
/// (`self` not empty, one per ray: the origin of the ray's own lookup in xyz, the side it leaves
/// on in w, `facing`) are looked up as the runtime looks up the mesh a ray leaves
/// (gf_trace_leaving, beyond self_t_min; first hits), and traced by the BVH from their t_min.
struct ProbeQuery {
  bool bvh = false;
  LookupMode mode = LookupMode::kRefined;
  bool last_hit = false;
  std::vector<glm::vec4> self;
  float self_t_min = 0.0f;
};

/// A probe's answers, one per ray: hits[i] = (1 for a hit else 0, t, u, v), u, v the
/// geometry-image uv (field) or the barycentrics of corners 1 and 2 (BVH); normals[i] the unit
/// normal at the hit; ms, the time of one pass over all rays (the median of the timed passes,
/// each from a finished GPU to its end), 0 when none was timed.
struct ProbeResult {
  std::vector<glm::vec4> hits;
  std::vector<glm::vec3> normals;
  double ms = 0.0;
};

/// Queries `rays` against asset `asset` of `assets` as `query` says: one pass, then `timed` timed
/// passes. Needs a current GL context; `shader_dir` holds the shaders.
bool probe_rays_gpu(const GpuAssets& assets, int asset, const std::vector<Ray>& rays,
                    const ProbeQuery& query, int timed, const std::string& shader_dir,
                    ProbeResult& result, std::string& error);

}  // namespace gfield
