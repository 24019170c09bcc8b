#pragma once
// Geometry-field lookups on the GPU for rays given by the caller (shaders/field_probe.frag): the
// GPU side of the CPU/GPU agreement check. One fragment per ray, rays in mesh coordinates.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/field_lookup.hpp"
#include "runtime/gpu_assets.hpp"

namespace gfield {

/// Looks up `rays` against asset `asset` of `assets` in `mode` (first or last hit). `hits[i]` =
/// (1 for a hit else 0, t, u, v). Needs a current GL context; `shader_dir` holds the shaders.
bool probe_field_gpu(const GpuAssets& assets, int asset, const std::vector<Ray>& rays,
                     LookupMode mode, bool last_hit, const std::string& shader_dir,
                     std::vector<glm::vec4>& hits, std::string& error);

}  // namespace gfield
