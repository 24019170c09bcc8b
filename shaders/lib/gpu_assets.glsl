// The scene's geometry images and geometry fields on the GPU (runtime/gpu_assets.hpp): four
// 2D-array textures read with texelFetch (positions, normals, albedo: each geometry image a
// square of a layer, runtime/image_atlas.hpp; the fields' nearest-hit tables, one layer per
// field, the uvs as the contract's codes, gf_decode_field_texel) and one storage buffer of the
// fields' line tables and interior hits (BUFFER_FIELD_LINES). A lookup first selects its asset
// with gs_select_asset(); the functions that shaders/lib/field_lines.glsl and field_lookup.glsl
// expect then read that asset's layers.

#include "lib/contract.glsl"
#include "lib/work.glsl"

layout(binding = UNIT_GI_POSITIONS) uniform sampler2DArray u_gi_positions;  // xyz P, w A
layout(binding = UNIT_GI_NORMALS) uniform sampler2DArray u_gi_normals;      // xyz unit normal
layout(binding = UNIT_FIELDS) uniform sampler2DArray u_fields;  // xy uv code, texel (column, entry)
layout(binding = UNIT_GI_ALBEDO) uniform sampler2DArray u_gi_albedo;  // rgb linear albedo
#ifdef GL_ES
// Word i of BUFFER_FIELD_LINES, at texel (i % WEB_TEXEL_ROW, i / WEB_TEXEL_ROW).
uniform highp usampler2D u_field_words;
uint gs_field_word(int i) {
  return texelFetch(u_field_words, ivec2(i % WEB_TEXEL_ROW, i / WEB_TEXEL_ROW), 0).r;
}
#else
layout(std430, binding = BUFFER_FIELD_LINES) readonly buffer FieldLines { uint gs_field_words[]; };
uint gs_field_word(int i) { return gs_field_words[i]; }
#endif

int gs_layer = 0;
ivec2 gs_image_origin = ivec2(0);
int gs_samples_per_side = 0;
int gs_image_size = 2;
int gs_field_layer = 0;
int gs_field_lines = 0;
int gs_field_interior = 0;
int gs_field_layers = 1;
int gs_field_bits = 32;
vec3 gs_box_min = vec3(0.0f);
vec3 gs_box_max = vec3(1.0f);

// image_layer, samples_per_side, image_size: GpuObject.asset.xyz; the image's corner in its
// layer: GpuObject.image.xy; the field's layer, line table, interior hits, bits + 256 layers:
// GpuObject.field; the box: GpuObject.box_min/box_max.
void gs_select_asset(ivec3 asset, ivec2 image_origin, ivec4 field, vec3 box_min, vec3 box_max) {
  gs_layer = asset.x;
  gs_image_origin = image_origin;
  gs_samples_per_side = asset.y;
  gs_image_size = asset.z;
  gs_field_layer = field.x;
  gs_field_lines = field.y;
  gs_field_interior = field.z;
  gs_field_bits = field.w % 256;
  gs_field_layers = field.w / 256;
  gs_box_min = box_min;
  gs_box_max = box_max;
}

int gf_samples_per_side() { return gs_samples_per_side; }
int gf_field_layers() { return gs_field_layers; }
vec2 gf_field_nearest_texel(int entry, int column) {
  WORK_ADD(WORK_FIELD_FETCHES, 1);
  vec2 texel = texelFetch(u_fields, ivec3(column, entry, gs_field_layer), 0).xy;
  return gf_decode_field_texel(texel, gs_field_bits);
}
uint gf_field_word(int i) {
  WORK_ADD(WORK_FIELD_FETCHES, 1);
  return gs_field_word(gs_field_lines + i);
}
// Interior hit i: two 8-bit codes (u low) in half a word, two 16-bit codes in a word, or two
// floats in two words (runtime/gpu_assets.cpp, gfield/gpu_storage.hpp: field_interior_words).
vec2 gf_field_interior_texel(int i) {
  WORK_ADD(WORK_FIELD_FETCHES, 1);
  // One word holds both codes below 32 bits: a word's half (8 bits) or the whole word (16).
  bool split = gs_field_bits == 32;
  int word = gs_field_bits == 8 ? i / 2 : (split ? 2 * i : i);
  uint w = gs_field_word(gs_field_interior + word);
  if (split) {
    return vec2(uintBitsToFloat(w), uintBitsToFloat(gs_field_word(gs_field_interior + word + 1)));
  }
  int bits = gs_field_bits;
  uint mask = (1u << uint(bits)) - 1u;
  w >>= uint(bits == 8 ? 16 * (i % 2) : 0);
  return vec2(gf_decode_field_code(float(w & mask), bits),
              gf_decode_field_code(float((w >> uint(bits)) & mask), bits));
}
int gf_image_size() { return gs_image_size; }
// Texel (i, j) of the selected image (0 <= i, j < n) in its layer.
ivec3 gs_image_texel(int i, int j) {
  return ivec3(gs_image_origin + ivec2(i, j), gs_layer);
}
vec4 gf_image_texel(int i, int j) {
  WORK_ADD(WORK_IMAGE_FETCHES, 1);
  return texelFetch(u_gi_positions, gs_image_texel(i, j), 0);
}
vec3 gf_image_normal_texel(int i, int j) {
  WORK_ADD(WORK_IMAGE_FETCHES, 1);
  return texelFetch(u_gi_normals, gs_image_texel(i, j), 0).xyz;
}
// The selected asset's albedo at geometry-image uv: bilinear between texel centres, clamped to
// the edge (gfield::sample_albedo).
vec3 gs_image_albedo(vec2 uv) {
  vec2 p = uv * float(gs_image_size) - 0.5f;
  vec2 f = floor(p);
  vec2 w = p - f;
  ivec2 i0 = clamp(ivec2(f), ivec2(0), ivec2(gs_image_size - 1));
  ivec2 i1 = clamp(ivec2(f) + 1, ivec2(0), ivec2(gs_image_size - 1));
  vec3 a = texelFetch(u_gi_albedo, gs_image_texel(i0.x, i0.y), 0).rgb;
  vec3 b = texelFetch(u_gi_albedo, gs_image_texel(i1.x, i0.y), 0).rgb;
  vec3 c = texelFetch(u_gi_albedo, gs_image_texel(i0.x, i1.y), 0).rgb;
  vec3 d = texelFetch(u_gi_albedo, gs_image_texel(i1.x, i1.y), 0).rgb;
  return mix(mix(a, b, w.x), mix(c, d, w.x), w.y);
}

vec3 gf_box_min() { return gs_box_min; }
vec3 gf_box_max() { return gs_box_max; }

#define GF_COUNT(kind, n) WORK_ADD(kind, n)
#include "lib/field_lines.glsl"
#include "lib/field_lookup.glsl"
