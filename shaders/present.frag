#version 450
// Shows the linear-radiance frame on an 8-bit display: clamp and sRGB encoding (as PNG output).
#include "lib/contract.glsl"

layout(binding = UNIT_FRAME) uniform sampler2D u_frame;
layout(location = 0) out vec4 o_color;

vec3 linear_to_srgb(vec3 v) {
  v = clamp(v, 0.0f, 1.0f);
  return mix(v * 12.92f, 1.055f * pow(v, vec3(1.0f / 2.4f)) - 0.055f, greaterThan(v, vec3(0.0031308f)));
}

void main() { o_color = vec4(linear_to_srgb(texelFetch(u_frame, ivec2(gl_FragCoord.xy), 0).rgb), 1.0f); }
