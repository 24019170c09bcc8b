#pragma once
// What a scene's assets take on the GPU, one line per mesh (the viewer's panel, --bench).

#include <string>

#include "gfield/scene.hpp"
#include "runtime/gpu_assets.hpp"

namespace gfield {

/// One line per asset: "NAME: image 10.5 MB, field RG8 + line table 23.0 MB (up to 8 hits a
/// line)" (the scene's mesh files),
/// with ", BVH 1.2 MB" where BVHs are loaded and "no field" for a mesh without one.
std::string asset_memory_lines(const Scene& scene, const GpuAssets& assets);

}  // namespace gfield
