#version 450
// One mesh query per pixel for rays given in textures (origin + t_min, direction + t_max, mesh
// coordinates): a geometry-field lookup (gf_trace; with PROBE_LEAVING, of rays leaving the
// surface as the runtime looks up the mesh a ray leaves, gf_trace_leaving), for comparing the
// GPU lookup with the CPU one and timing it; or with PROBE_BVH the exact hit through the mesh's
// BVH as the runtime takes it (bvh_mesh_hit's walk and shading normal). Outputs: (hit, t, u, v),
// u, v the geometry-image uv (field) or the barycentrics of corners 1 and 2 (BVH); the unit normal.
// Both libraries, whichever route: an include is expanded once, where it first appears, so
// neither may sit in a branch of the preprocessor.
#include "lib/gpu_assets.glsl"
#include "lib/gpu_bvh.glsl"

#ifdef PROBE_BVH
uniform int u_bvh_root;  // the mesh's BVH (GpuAsset::bvh_root)
#else
uniform ivec3 u_asset;  // image layer, N, image size n (GpuObject.asset)
uniform ivec2 u_image_origin;  // the image's corner in its layer (GpuObject.image)
uniform ivec4 u_field;  // the field on the GPU (GpuObject.field)
uniform vec3 u_box_min;
uniform vec3 u_box_max;
uniform int u_mode;
#ifdef PROBE_LEAVING
uniform float u_self_t_min;  // beyond which the lookup of a ray's own origin looks
layout(binding = UNIT_PROBE_SELF) uniform sampler2D u_ray_self;  // self origin (xyz), facing (w)
#else
uniform bool u_last;
#endif
#endif

layout(binding = UNIT_PROBE_ORIGINS) uniform sampler2D u_ray_origins;
layout(binding = UNIT_PROBE_DIRECTIONS) uniform sampler2D u_ray_directions;

// The rays given: the grid's texels past them, and the lanes past the grid's edge that a GPU may
// shade with the rest of a block (llvmpipe shades 4 x 4 blocks), read no ray. Such a lane would
// read zeros, a ray of zero direction, that the BVH walk spends tens of ms on in llvmpipe.
uniform int u_ray_count;

layout(location = 0) out vec4 o_hit;
layout(location = 1) out vec4 o_normal;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  o_hit = vec4(0.0f, 0.0f, -1.0f, -1.0f);
  o_normal = vec4(0.0f);
  if (pixel.x >= PROBE_WIDTH || pixel.y * PROBE_WIDTH + pixel.x >= u_ray_count) {
    return;
  }
  vec4 origin = texelFetch(u_ray_origins, pixel, 0);
  vec4 direction = texelFetch(u_ray_directions, pixel, 0);
#ifdef PROBE_BVH
  GbHit h = gb_trace(u_bvh_root, origin.xyz, direction.xyz, origin.w, direction.w);
  if (h.hit) {
    o_hit = vec4(1.0f, h.t, h.bary);
    o_normal = vec4(gb_shading_normal(gb_shading(h.slot), h.bary), 0.0f);
  }
#else
  gs_select_asset(u_asset, u_image_origin, u_field, u_box_min, u_box_max);
#ifdef PROBE_LEAVING
  vec4 self = texelFetch(u_ray_self, pixel, 0);
  GfHit h = gf_trace_leaving(origin.xyz, direction.xyz, origin.w, direction.w, self.xyz,
                             u_self_t_min, self.w, u_mode, false);
#else
  GfHit h = gf_trace(origin.xyz, direction.xyz, origin.w, direction.w, u_mode, u_last);
#endif
  o_hit = h.hit ? vec4(1.0f, h.t, h.uv) : vec4(0.0f, 0.0f, -1.0f, -1.0f);
  o_normal = vec4(h.normal, 0.0f);
#endif
}
