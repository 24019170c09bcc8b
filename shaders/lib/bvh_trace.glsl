// Exact ray tracing of a mesh through its bounding volume hierarchy (geometry/mesh_bvh.hpp): the
// peer an engine programmer would use instead of a geometry field.
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md; float),
// included by geometry/mesh_bvh.cpp (inside a struct whose members supply the fetches) and by
// shaders/lib/gpu_bvh.glsl.
//
// The includer defines, before including this file (GLSL) or as members (C++):
//   vec3 gb_node_lo(int i);  vec3 gb_node_hi(int i);  bounds of node i (mesh coordinates)
//   int  gb_node_first(int i);  inner node: its left child (the right one is first + 1); leaf:
//                               the slot of its first triangle
//   int  gb_node_count(int i);  triangles of a leaf (0: an inner node)
//   vec3 gb_triangle_p0(int s); vec3 gb_triangle_e1(int s); vec3 gb_triangle_e2(int s);
//                               the triangle in slot s: corner 0 and the edges to corners 1, 2
// Rays are origin + t * direction (mesh coordinates), t in [t_min, t_max]; t is along the given
// direction.

#ifndef __cplusplus
#include "lib/contract.glsl"
#endif

// Pending far children at most: the builder keeps the tree shallower than this.
GF_CONST int GB_STACK_SIZE = 64;

struct GbHit {
  bool hit;
  float t;
  int slot;       // the triangle's slot (leaf order)
  vec2 bary;      // barycentrics of corners 1 and 2
  int nodes;      // nodes whose bounds were tested
  int triangles;  // triangles tested
};

// Whether the ray enters the box [lo, hi] within [t_min, t_max]; t_near: where.
bool gb_box(vec3 lo, vec3 hi, vec3 o, vec3 inv_d, float t_min, float t_max,
            GF_OUT(float) t_near) {
  vec3 ta = (lo - o) * inv_d;
  vec3 tb = (hi - o) * inv_d;
  vec3 t_lo = min(ta, tb);
  vec3 t_hi = max(ta, tb);
  t_near = max(max(t_lo.x, t_lo.y), max(t_lo.z, t_min));
  float t_far = min(min(t_hi.x, t_hi.y), min(t_hi.z, t_max));
  return t_near <= t_far;
}

// Moller-Trumbore: the ray against the triangle in slot s, keeping the nearest hit in h.
void gb_triangle(int s, vec3 o, vec3 d, float t_min, GF_INOUT(GbHit) h) {
  h.triangles++;
  vec3 e1 = gb_triangle_e1(s);
  vec3 e2 = gb_triangle_e2(s);
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0f) {
    return;
  }
  float inv = 1.0f / det;
  vec3 r = o - gb_triangle_p0(s);
  float u = dot(r, p) * inv;
  if (u < 0.0f || u > 1.0f) {
    return;
  }
  vec3 q = cross(r, e1);
  float v = dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) {
    return;
  }
  float t = dot(e2, q) * inv;
  if (t < t_min || t > h.t) {
    return;
  }
  h.hit = true;
  h.t = t;
  h.slot = s;
  h.bary = vec2(u, v);
}

// The nearest triangle hit of o + t d, t in [t_min, t_max], in the BVH whose root is node `root`
// (nearer child first, a stack of far children with their entry distances).
GbHit gb_trace(int root, vec3 o, vec3 d, float t_min, float t_max) {
  GbHit h;
  h.hit = false;
  h.t = t_max;
  h.slot = -1;
  h.bary = vec2(0.0f);
  h.nodes = 1;
  h.triangles = 0;
  // A zero component of d would make 0 * inf = NaN in the slab test: a tiny one instead.
  vec3 safe = vec3(abs(d.x) < 1.0e-30f ? 1.0e-30f : d.x, abs(d.y) < 1.0e-30f ? 1.0e-30f : d.y,
                   abs(d.z) < 1.0e-30f ? 1.0e-30f : d.z);
  vec3 inv_d = vec3(1.0f) / safe;
  float t_near;
  if (root < 0 || !gb_box(gb_node_lo(root), gb_node_hi(root), o, inv_d, t_min, t_max, t_near)) {
    return h;
  }
  int stack_node[GB_STACK_SIZE];
  float stack_t[GB_STACK_SIZE];
  int top = 0;
  int node = root;
  while (node >= 0) {
    int count = gb_node_count(node);
    int first = gb_node_first(node);
    int next = -1;
    if (count > 0) {
      for (int i = 0; i < count; i++) {
        gb_triangle(first + i, o, d, t_min, h);
      }
    } else {
      float t_left;
      float t_right;
      h.nodes += 2;
      bool left = gb_box(gb_node_lo(first), gb_node_hi(first), o, inv_d, t_min, h.t, t_left);
      bool right =
          gb_box(gb_node_lo(first + 1), gb_node_hi(first + 1), o, inv_d, t_min, h.t, t_right);
      if (left && right) {
        bool left_first = t_left <= t_right;
        next = left_first ? first : first + 1;
        if (top < GB_STACK_SIZE) {
          stack_node[top] = left_first ? first + 1 : first;
          stack_t[top] = left_first ? t_right : t_left;
          top++;
        }
      } else if (left) {
        next = first;
      } else if (right) {
        next = first + 1;
      }
    }
    while (next < 0 && top > 0) {  // the nearest pending child the ray can still reach
      top--;
      if (stack_t[top] <= h.t) {
        next = stack_node[top];
      }
    }
    node = next;
  }
  return h;
}
