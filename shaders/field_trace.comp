#version 450
// The geometry-field tracing pass as a compute dispatch: one invocation per pixel
// (lib/field_trace.glsl), written into the frame's colour and hit textures by image stores. The
// runtime reads the group size from the program.
// A group traces one tile of the frame, the tiles in bit-reversed order: a contiguous run of
// groups covers tiles spread over the whole frame, so that a driver that hands each thread such
// a run (llvmpipe) gives every thread a like share of the expensive parts of the picture.
#define GF_COMPUTE 1
#include "lib/field_trace.glsl"

// 8x8: the order of pixels within a tile below is written for this size.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = IMAGE_TRACE_COLOR) uniform writeonly image2D u_color;  // as o_color
layout(rgba32f, binding = IMAGE_TRACE_HITS) uniform writeonly image2D u_hits;    // as o_hits
uniform int u_tile_columns;  // the frame's tiles per row
uniform int u_tile_bits;     // the dispatch holds 2^u_tile_bits groups, at least the tiles, >= 1

void main() {
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  uint tile = bitfieldReverse(group) >> uint(32 - u_tile_bits);
  ivec2 corner = ivec2(int(tile) % u_tile_columns, int(tile) / u_tile_columns);
  // Each run of 8 invocations covers a 4x2 block of the 8x8 tile, as a CPU renderer's fragment
  // shading packs pixels into its SIMD vectors; each run of 32 still covers 8x4 pixels.
  uint i = gl_LocalInvocationIndex;
  ivec2 in_tile = ivec2(((i >> 3u) & 1u) * 4u + (i & 3u), (i >> 4u) * 2u + ((i >> 2u) & 1u));
  ivec2 pixel = corner * ivec2(gl_WorkGroupSize.xy) + in_tile;
  if (any(greaterThanEqual(pixel, imageSize(u_color)))) return;
  vec4 color, hits;
  trace_pixel(pixel, color, hits);
  imageStore(u_color, pixel, color);
  imageStore(u_hits, pixel, hits);
}
