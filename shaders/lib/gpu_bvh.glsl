// The meshes' BVHs on the GPU (runtime/gpu_bvh.hpp): the fetches shaders/lib/bvh_trace.glsl
// expects, and a mesh's exact hit with the rasterised mesh's shading (the G-buffer's: corner
// normals, texture coordinates and base colours interpolated at the hit).

#include "lib/contract.glsl"
#include "lib/textures.glsl"
#include "lib/work.glsl"

#ifdef GL_ES
// The three buffers as RGBA32F textures, element i's vec4 k at texel j = i * (vec4s per element)
// + k, (j % WEB_TEXEL_ROW, j / WEB_TEXEL_ROW).
uniform highp sampler2D u_bvh_nodes;      // GpuBvhNode: 2 texels
uniform highp sampler2D u_bvh_triangles;  // GpuBvhTriangle: 3 texels
uniform highp sampler2D u_bvh_shading;    // GpuBvhShading: 6 texels
vec4 gb_texel(highp sampler2D t, int j) {
  return texelFetch(t, ivec2(j % WEB_TEXEL_ROW, j / WEB_TEXEL_ROW), 0);
}
vec4 gb_node_lo4(int i) { return gb_texel(u_bvh_nodes, 2 * i); }
vec4 gb_node_hi4(int i) { return gb_texel(u_bvh_nodes, 2 * i + 1); }
vec4 gb_triangle_p0w(int s) { return gb_texel(u_bvh_triangles, 3 * s); }
vec3 gb_triangle_e1(int s) { return gb_texel(u_bvh_triangles, 3 * s + 1).xyz; }
vec3 gb_triangle_e2(int s) { return gb_texel(u_bvh_triangles, 3 * s + 2).xyz; }
GpuBvhShading gb_shading(int s) {
  GpuBvhShading h;
  h.normal_u0 = gb_texel(u_bvh_shading, 6 * s);
  h.normal_u1 = gb_texel(u_bvh_shading, 6 * s + 1);
  h.normal_u2 = gb_texel(u_bvh_shading, 6 * s + 2);
  h.base_v0 = gb_texel(u_bvh_shading, 6 * s + 3);
  h.base_v1 = gb_texel(u_bvh_shading, 6 * s + 4);
  h.base_v2 = gb_texel(u_bvh_shading, 6 * s + 5);
  return h;
}
#else
layout(std430, binding = BUFFER_BVH_NODES) readonly buffer BvhNodes { GpuBvhNode bvh_nodes[]; };
layout(std430, binding = BUFFER_BVH_TRIANGLES) readonly buffer BvhTriangles {
  GpuBvhTriangle bvh_triangles[];
};
layout(std430, binding = BUFFER_BVH_SHADING) readonly buffer BvhShading {
  GpuBvhShading bvh_shading[];
};
vec4 gb_node_lo4(int i) { return bvh_nodes[i].lo; }
vec4 gb_node_hi4(int i) { return bvh_nodes[i].hi; }
vec4 gb_triangle_p0w(int s) { return bvh_triangles[s].p0; }
vec3 gb_triangle_e1(int s) { return bvh_triangles[s].e1.xyz; }
vec3 gb_triangle_e2(int s) { return bvh_triangles[s].e2.xyz; }
GpuBvhShading gb_shading(int s) { return bvh_shading[s]; }
#endif

vec3 gb_node_lo(int i) { return gb_node_lo4(i).xyz; }
vec3 gb_node_hi(int i) { return gb_node_hi4(i).xyz; }
int gb_node_first(int i) { return floatBitsToInt(gb_node_lo4(i).w); }
int gb_node_count(int i) { return floatBitsToInt(gb_node_hi4(i).w); }
vec3 gb_triangle_p0(int s) { return gb_triangle_p0w(s).xyz; }

#include "lib/bvh_trace.glsl"

// The rasterised mesh's shading normal (unit) at barycentrics `bary` (corners 1 and 2) of a
// triangle whose shading is s: its corner normals interpolated.
vec3 gb_shading_normal(GpuBvhShading s, vec2 bary) {
  vec3 w = vec3(1.0f - bary.x - bary.y, bary.x, bary.y);
  return normalize(w.x * s.normal_u0.xyz + w.y * s.normal_u1.xyz + w.z * s.normal_u2.xyz);
}

// A mesh's exact hit (mesh coordinates): t along the given direction, the interpolated shading
// normal (unit), texture coordinates, and the base colour there (the mesh's own texture looked
// up at level 0).
struct BvhMeshHit {
  bool hit;
  float t;
  vec3 position;
  vec3 normal;
  vec2 uv;
  vec3 base_color;
};

#if defined(GL_ES) && defined(GF_EXTERNAL_BVH)
// A BVH of the web page's own in place of gfield's (the player's three-mesh-bvh method,
// web/player/gfield-three-mesh-bvh.js, which appends this function's definition to the stage):
// the hit of the mesh whose gfield BVH has root `root`, as bvh_mesh_hit gives it.
BvhMeshHit external_bvh_hit(int root, vec3 o, vec3 d, float t_min, float t_max);
#endif

BvhMeshHit bvh_mesh_hit(int root, vec3 o, vec3 d, float t_min, float t_max) {
#if defined(GL_ES) && defined(GF_EXTERNAL_BVH)
  WORK_ADD(WORK_BVH_TRAVERSALS, 1);  // its nodes and triangles: counted by the definition
  return external_bvh_hit(root, o, d, t_min, t_max);
#else
  BvhMeshHit m;
  GbHit h = gb_trace(root, o, d, t_min, t_max);
  WORK_ADD(WORK_BVH_TRAVERSALS, 1);
  WORK_ADD(WORK_BVH_NODES, h.nodes);
  WORK_ADD(WORK_BVH_TRIANGLES, h.triangles);
  m.hit = h.hit;
  if (!h.hit) return m;
  GpuBvhShading s = gb_shading(h.slot);
  vec3 w = vec3(1.0f - h.bary.x - h.bary.y, h.bary.x, h.bary.y);
  m.t = h.t;
  m.position = o + h.t * d;
  m.normal = gb_shading_normal(s, h.bary);
  m.uv = w.x * vec2(s.normal_u0.w, s.base_v0.w) + w.y * vec2(s.normal_u1.w, s.base_v1.w) +
         w.z * vec2(s.normal_u2.w, s.base_v2.w);
  vec3 base = w.x * s.base_v0.rgb + w.y * s.base_v1.rgb + w.z * s.base_v2.rgb;
  float layer = gb_triangle_p0w(h.slot).w;
  m.base_color = layer < -0.5f ? base
                               : base * textureLod(u_mesh_textures, vec3(m.uv, layer), 0.0f).rgb;
  return m;
#endif
}
