#pragma once
// The CPU side of shaders/lib/contract.glsl: the codes, binding slots, std430 buffer layouts and
// camera ray that the runtime and the shaders share, compiled from the same file into namespace
// gfield::gpu (GLM types standing for GLSL's; docs/architecture.md, "The CPU/GPU dialect").

#include <cstddef>

#include "gfield/glsl_names.hpp"

namespace gfield::gpu {
// The GLSL vocabulary contract.glsl uses, declared one by one: nothing else of GLM or of the
// dialect is visible through gfield::gpu.
using glsl::ivec4;
using glsl::mat4;
using glsl::min;
using glsl::normalize;
using glsl::round;
using glsl::tan;
using glsl::uint;
using glsl::vec2;
using glsl::vec3;
using glsl::vec4;

#include "gfield/glsl_begin.hpp"

#include "contract.glsl"  // shaders/lib/ in the source tree, beside this header when installed

#include "gfield/glsl_end.hpp"

// std430 offsets are the C++ ones: every member is 16-byte sized and aligned in both.
static_assert(sizeof(GpuObject) == 320 && offsetof(GpuObject, kind) == 256 &&
              offsetof(GpuObject, asset) == 272 && offsetof(GpuObject, field) == 288 &&
              offsetof(GpuObject, image) == 304);
static_assert(sizeof(GpuLight) == 48 && offsetof(GpuLight, color) == 32);
static_assert(sizeof(GpuBvhNode) == 32 && sizeof(GpuBvhTriangle) == 48 &&
              sizeof(GpuBvhShading) == 96);
}  // namespace gfield::gpu
