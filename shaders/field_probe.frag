#version 450
// One geometry-field lookup per pixel for rays given in two textures (origin + t_min, direction +
// t_max, mesh coordinates), for comparing the GPU lookup with the CPU one. Output: (hit, t, u, v).
#include "lib/gpu_assets.glsl"

layout(binding = UNIT_PROBE_ORIGINS) uniform sampler2D u_ray_origins;
layout(binding = UNIT_PROBE_DIRECTIONS) uniform sampler2D u_ray_directions;
uniform ivec3 u_asset;  // image layer, N, image size n (GpuObject.asset)
uniform ivec2 u_image_origin;  // the image's corner in its layer (GpuObject.image)
uniform ivec4 u_field;  // the field on the GPU (GpuObject.field)
uniform vec3 u_box_min;
uniform vec3 u_box_max;
uniform int u_mode;
uniform bool u_last;

layout(location = 0) out vec4 o_hit;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 origin = texelFetch(u_ray_origins, pixel, 0);
  vec4 direction = texelFetch(u_ray_directions, pixel, 0);
  gs_select_asset(u_asset, u_image_origin, u_field, u_box_min, u_box_max);
  GfHit h = gf_trace(origin.xyz, direction.xyz, origin.w, direction.w, u_mode, u_last);
  o_hit = h.hit ? vec4(1.0f, h.t, h.uv) : vec4(0.0f, 0.0f, -1.0f, -1.0f);
}
