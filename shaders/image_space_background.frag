#version 450
// The environment behind everything, along each pixel's camera ray (exact, not a cube map).
#include "lib/image_space.glsl"

layout(location = 0) out vec4 o_color;

void main() { o_color = vec4(environment_radiance(camera_direction()), 1.0f); }
