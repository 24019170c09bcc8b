// The scene's objects (the contract's GpuObject, shaders/lib/contract.glsl) in their storage
// buffer, filled by runtime/gpu_scene.cpp.

#include "lib/contract.glsl"

#ifdef GL_ES
// WebGL2 has no storage buffers: a uniform block of at most WEB_MAX_OBJECTS (std140, which lays
// out vec4 / ivec4 / mat4 members as std430 does).
layout(std140) uniform Objects { GpuObject objects[WEB_MAX_OBJECTS]; };
#else
layout(std430, binding = BUFFER_OBJECTS) readonly buffer Objects { GpuObject objects[]; };
#endif
