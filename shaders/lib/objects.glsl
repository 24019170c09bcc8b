// The scene's objects (the contract's GpuObject, shaders/lib/contract.glsl) in their storage
// buffer, filled by runtime/gpu_scene.cpp.

#include "lib/contract.glsl"

layout(std430, binding = BUFFER_OBJECTS) readonly buffer Objects { GpuObject objects[]; };
