// The scene's geometry images and geometry fields on the GPU (runtime/gpu_assets.hpp): four
// 2D-array textures (positions, normals, albedo, fields), one layer per asset, read with
// texelFetch. A lookup first selects its asset
// with gs_select_asset(); the functions that shaders/lib/field_lookup.glsl expects then read
// that asset's layer.

#include "lib/contract.glsl"

layout(binding = UNIT_GI_POSITIONS) uniform sampler2DArray u_gi_positions;  // xyz P, w A
layout(binding = UNIT_GI_NORMALS) uniform sampler2DArray u_gi_normals;      // xyz unit normal
layout(binding = UNIT_FIELDS) uniform sampler2DArray u_fields;  // xy uv, texel (exit, entry)
layout(binding = UNIT_GI_ALBEDO) uniform sampler2DArray u_gi_albedo;  // rgb linear albedo

int gs_layer = 0;
int gs_samples_per_side = 0;
int gs_image_size = 2;
vec3 gs_box_min = vec3(0.0f);
vec3 gs_box_max = vec3(1.0f);

void gs_select_asset(int layer, int samples_per_side, int image_size, vec3 box_min,
                     vec3 box_max) {
  gs_layer = layer;
  gs_samples_per_side = samples_per_side;
  gs_image_size = image_size;
  gs_box_min = box_min;
  gs_box_max = box_max;
}

int gf_samples_per_side() { return gs_samples_per_side; }
vec2 gf_field_texel(int entry, int exit) {
  return texelFetch(u_fields, ivec3(exit, entry, gs_layer), 0).xy;
}
int gf_image_size() { return gs_image_size; }
vec3 gf_image_position_texel(int i, int j) {
  return texelFetch(u_gi_positions, ivec3(i, j, gs_layer), 0).xyz;
}
vec3 gf_image_normal_texel(int i, int j) {
  return texelFetch(u_gi_normals, ivec3(i, j, gs_layer), 0).xyz;
}
// The selected asset's albedo at geometry-image uv: bilinear between texel centres, clamped to
// the edge (gfield::sample_albedo).
vec3 gs_image_albedo(vec2 uv) {
  vec2 p = uv * float(gs_image_size) - 0.5f;
  vec2 f = floor(p);
  vec2 w = p - f;
  ivec2 i0 = clamp(ivec2(f), ivec2(0), ivec2(gs_image_size - 1));
  ivec2 i1 = clamp(ivec2(f) + 1, ivec2(0), ivec2(gs_image_size - 1));
  vec3 a = texelFetch(u_gi_albedo, ivec3(i0.x, i0.y, gs_layer), 0).rgb;
  vec3 b = texelFetch(u_gi_albedo, ivec3(i1.x, i0.y, gs_layer), 0).rgb;
  vec3 c = texelFetch(u_gi_albedo, ivec3(i0.x, i1.y, gs_layer), 0).rgb;
  vec3 d = texelFetch(u_gi_albedo, ivec3(i1.x, i1.y, gs_layer), 0).rgb;
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

vec3 gf_box_min() { return gs_box_min; }
vec3 gf_box_max() { return gs_box_max; }

#include "lib/field_lookup.glsl"
