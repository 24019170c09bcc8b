// The meshes' BVHs on the GPU (runtime/gpu_bvh.hpp): the fetches shaders/lib/bvh_trace.glsl
// expects, and a mesh's exact hit with the rasterised mesh's shading (the G-buffer's: corner
// normals, texture coordinates and base colours interpolated at the hit).

#include "lib/contract.glsl"
#include "lib/textures.glsl"
#include "lib/work.glsl"

layout(std430, binding = BUFFER_BVH_NODES) readonly buffer BvhNodes { GpuBvhNode bvh_nodes[]; };
layout(std430, binding = BUFFER_BVH_TRIANGLES) readonly buffer BvhTriangles {
  GpuBvhTriangle bvh_triangles[];
};
layout(std430, binding = BUFFER_BVH_SHADING) readonly buffer BvhShading {
  GpuBvhShading bvh_shading[];
};

vec3 gb_node_lo(int i) { return bvh_nodes[i].lo.xyz; }
vec3 gb_node_hi(int i) { return bvh_nodes[i].hi.xyz; }
int gb_node_first(int i) { return floatBitsToInt(bvh_nodes[i].lo.w); }
int gb_node_count(int i) { return floatBitsToInt(bvh_nodes[i].hi.w); }
vec3 gb_triangle_p0(int s) { return bvh_triangles[s].p0.xyz; }
vec3 gb_triangle_e1(int s) { return bvh_triangles[s].e1.xyz; }
vec3 gb_triangle_e2(int s) { return bvh_triangles[s].e2.xyz; }

#include "lib/bvh_trace.glsl"

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

BvhMeshHit bvh_mesh_hit(int root, vec3 o, vec3 d, float t_min, float t_max) {
  BvhMeshHit m;
  GbHit h = gb_trace(root, o, d, t_min, t_max);
  WORK_ADD(WORK_BVH_TRAVERSALS, 1);
  WORK_ADD(WORK_BVH_NODES, h.nodes);
  WORK_ADD(WORK_BVH_TRIANGLES, h.triangles);
  m.hit = h.hit;
  if (!h.hit) return m;
  GpuBvhShading s = bvh_shading[h.slot];
  vec3 w = vec3(1.0f - h.bary.x - h.bary.y, h.bary.x, h.bary.y);
  m.t = h.t;
  m.position = o + h.t * d;
  m.normal = normalize(w.x * s.normal_u0.xyz + w.y * s.normal_u1.xyz + w.z * s.normal_u2.xyz);
  m.uv = w.x * vec2(s.normal_u0.w, s.base_v0.w) + w.y * vec2(s.normal_u1.w, s.base_v1.w) +
         w.z * vec2(s.normal_u2.w, s.base_v2.w);
  vec3 base = w.x * s.base_v0.rgb + w.y * s.base_v1.rgb + w.z * s.base_v2.rgb;
  float layer = bvh_triangles[h.slot].p0.w;
  m.base_color = layer < -0.5f ? base
                               : base * textureLod(u_mesh_textures, vec3(m.uv, layer), 0.0f).rgb;
  return m;
}
