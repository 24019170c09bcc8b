#pragma once
// The CPU side of shaders/lib/contract.glsl: the codes, binding slots, std430 buffer layouts and
// camera ray that the runtime and the shaders share, compiled from the same file into namespace
// gfield::gpu (GLM types standing for GLSL's).

#include <cstddef>

#include <glm/glm.hpp>

namespace gfield::gpu {
using namespace glm;      // the GLSL vocabulary of contract.glsl
#include "contract.glsl"  // shaders/lib/ in the source tree, beside this header when installed

// std430 offsets are the C++ ones: every member is 16-byte sized and aligned in both.
static_assert(sizeof(GpuObject) == 320 && offsetof(GpuObject, kind) == 256 &&
              offsetof(GpuObject, asset) == 272 && offsetof(GpuObject, field) == 288 &&
              offsetof(GpuObject, image) == 304);
static_assert(sizeof(GpuLight) == 48 && offsetof(GpuLight, color) == 32);
static_assert(sizeof(GpuBvhNode) == 32 && sizeof(GpuBvhTriangle) == 48 &&
              sizeof(GpuBvhShading) == 96);
}  // namespace gfield::gpu
