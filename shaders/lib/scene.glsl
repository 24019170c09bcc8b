// The scene on the GPU: objects (analytic shapes and geometry-field meshes) and lights in
// shader storage buffers (runtime/gpu_scene.cpp fills them), the nearest hit of a world ray over
// all objects (Li et al. 2006, TraceRay step 1-2) with its albedo (a mesh's own base colour from
// its geometry image's albedo at the hit's uv), shadow rays and diffuse shading as the reference
// tracer does them (preprocess/reference_tracer.cpp). A mesh is looked up in its geometry field,
// or traced exactly through its BVH (shaders/lib/gpu_bvh.glsl) with u_intersect_bvh or when it
// has no field.

#include "lib/contract.glsl"
#include "lib/gpu_assets.glsl"
#include "lib/gpu_bvh.glsl"
#include "lib/objects.glsl"
#include "lib/shapes.glsl"
#include "lib/scene_environment.glsl"
#include "lib/textures.glsl"

// GpuObject, GpuLight and the MATERIAL_* codes are the contract's (shaders/lib/contract.glsl).
#ifdef GL_ES
layout(std140) uniform Lights { GpuLight lights[WEB_MAX_LIGHTS]; };  // objects.glsl says why
#else
layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
#endif

uniform int u_object_count;
uniform int u_light_count;
uniform vec3 u_ambient;
// The geometry-field method builds one program per setting (runtime/methods/geometry_field.cpp):
// GF_TRACE_MODE, the lookup mode (else the uniform u_mode); GF_FIELD_MESHES and GF_BVH_MESHES,
// 0 where no mesh is met that way; GF_FIELD_SHADOWS (below). llvmpipe runs every branch of a
// shader under a mask, so code a frame does not use costs as much as code it does.
#ifdef GF_TRACE_MODE
#define SCENE_LOOKUP_MODE GF_TRACE_MODE
#else
uniform int u_mode;  // GF_MODE_NEAREST, GF_MODE_LINEAR, GF_MODE_REFINED
#define SCENE_LOOKUP_MODE u_mode
#endif
#ifndef GF_FIELD_MESHES
#define GF_FIELD_MESHES 1
#endif
#ifndef GF_BVH_MESHES
#define GF_BVH_MESHES 1
#endif
// GF_FIELD_SHADOWS: 0 where no diffuse mesh is traced by its field, so that no shadow ray looks
// up the mesh it leaves (intersect_object's any_hit) and the lookup's any-hit doubt compiles away.
#ifndef GF_FIELD_SHADOWS
#define GF_FIELD_SHADOWS 1
#endif
// GF_CACHED_ENTRIES: 1 where the scene holds at most SCENE_CACHED_ENTRIES objects, so that
// trace_scene computes each object's order key once per ray (two matrix products and a box test
// each) instead of once per pass; a shader has no array of the scene's length.
#ifndef GF_CACHED_ENTRIES
#define GF_CACHED_ENTRIES 0
#endif
uniform bool u_self_reflection; // mesh objects look themselves up too
uniform bool u_intersect_bvh;   // every mesh through its BVH (else only those without a field)
uniform float u_scene_extent;   // diagonal of the scene bounds (ray offsets)

struct SceneHit {
  bool hit;
  float t;         // along the (unit) world direction
  int object;
  vec3 position;   // world
  vec3 normal;     // world, unit, out of the solid
  vec2 uv;         // analytic: texture coordinates; mesh: geometry-image uv
  vec3 albedo;     // diffuse hits found by trace_scene (or the G-buffer): the surface's albedo
  bool has_albedo;  // albedo set where the hit was found (a BVH hit), not from its uv
  float self_offset;  // rays leaving this point look its object up from this far off the
                      // surface (object_epsilon)
};

SceneHit scene_miss() {
  SceneHit h;
  h.hit = false;
  h.t = GF_FAR;
  h.object = -1;
  h.position = vec3(0.0f);
  h.normal = vec3(0.0f);
  h.uv = vec2(0.0f);
  h.albedo = vec3(0.0f);
  h.has_albedo = false;
  h.self_offset = 0.0f;
  return h;
}

// Whether mesh object k is traced through its BVH rather than looked up in its field.
bool traced_by_bvh(int k) {
  return objects[k].image.z >= 0 &&
         (u_intersect_bvh || objects[k].asset.y == 0 || objects[k].image.w != 0);
}

// Offset of rays leaving world point `p` of analytic shape k: beyond the float error of the
// intersection, which grows with the coordinates involved (the point's distance from the origin
// and from the shape's centre: a quad 1e6 wide is exact near its centre), not with the scene's
// extent (1e-5 of it lost the shadows on a floor of 1e4).
float analytic_epsilon(int k, vec3 p) {
  return 2.0e-5f * (length(p) + distance(p, objects[k].to_world[3].xyz)) +
         1.0e-9f * objects[k].absorption.w;
}

// Offset of rays leaving a surface point of object k (scene units). A ray starts 1e-4 of a mesh's
// size (for analytic shapes analytic_epsilon) off the surface along its normal (a larger start
// offset moves the paths: 1e-3 cost the glass spot 2.6 dB against the reference tracer); the
// lookup of the mesh it leaves starts `object_epsilon(k, rasterised)` off the surface and looks
// beyond 2 of them (SceneHit.self_offset, intersect_object). A point found by a field lookup lies
// on the geometry image: 1e-4 of the size. A point of the rasterised mesh (`rasterised`: the
// G-buffer's first hits) lies off the image by the image's deviation from the mesh, through which
// the lookup would find the surface the ray leaves: the image's ray offset (GpuObject.box_min.w:
// the deviation at 98% of the surface, at least 1e-4).
float object_epsilon(int k, bool rasterised, vec3 p) {
  if (objects[k].kind.x != SHAPE_MESH) return analytic_epsilon(k, p);
  if (traced_by_bvh(k)) return GF_MIN_RAY_OFFSET * objects[k].absorption.w;  // the mesh itself
  return (rasterised ? objects[k].box_min.w : GF_MIN_RAY_OFFSET) * objects[k].absorption.w;
}

// Offset of shadow rays from `hit` (they start there and look their object up beyond 2 of
// them): its self offset, for a mesh at least 10 times the least, 1e-3 of its size (with its
// self offset alone the diffuse spots of mirror-torus-instances and textured-mirror shade 0.2 dB
// further from the reference; with 1e-4 for every shadow ray the 256^2 spot of the synthetic
// mirror-spheres scene shadowed itself: 49.5 -> 43.4 dB).
float shadow_epsilon(SceneHit hit) {
  int k = hit.object;
  if (objects[k].kind.x != SHAPE_MESH) return hit.self_offset;
  return max(hit.self_offset, 10.0f * GF_MIN_RAY_OFFSET * objects[k].absorption.w);
}

// Makes mesh object k's geometry image and field the ones gf_* reads (gs_select_asset).
void select_mesh(int k) {
  gs_select_asset(objects[k].asset.xyz, objects[k].image.xy, objects[k].field,
                  objects[k].box_min.xyz, objects[k].box_max.xyz);
}

// The hit `g` of mesh object k (mesh coordinates, found by select_mesh(k) and gf_*) in world
// coordinates; a miss for a miss.
SceneHit world_mesh_hit(int k, GfHit g) {
  SceneHit h = scene_miss();
  if (!g.hit) return h;
  h.hit = true;
  h.t = g.t;
  h.object = k;
  h.position = (objects[k].to_world * vec4(g.position, 1.0f)).xyz;
  h.normal = normalize(transpose(mat3(objects[k].to_object)) * g.normal);
  h.uv = g.uv;
  h.self_offset = object_epsilon(k, false, h.position);
  return h;
}

// The exact hit `m` of mesh object k (mesh coordinates, from its BVH) in world coordinates, with
// the albedo the G-buffer would give it (its colour x its own base colour).
SceneHit world_bvh_hit(int k, BvhMeshHit m) {
  SceneHit h = scene_miss();
  if (!m.hit) return h;
  h.hit = true;
  h.t = m.t;
  h.object = k;
  h.position = (objects[k].to_world * vec4(m.position, 1.0f)).xyz;
  h.normal = normalize(transpose(mat3(objects[k].to_object)) * m.normal);
  h.uv = m.uv;
  h.albedo = objects[k].color.rgb * (objects[k].kind.z == TEXTURE_MESH ? m.base_color : vec3(1.0f));
  h.has_albedo = true;
  h.self_offset = object_epsilon(k, false, h.position);
  return h;
}

// How a ray looks up the object it leaves (the camera's: object -1): a mesh from `origin` (its
// start moved SceneHit.self_offset off the surface) beyond `t_min` (gf_trace_leaving); `facing`:
// +1 when it leaves into the open, -1 into the solid.
struct SelfLookup {
  int object;
  vec3 origin;
  float t_min;
  float facing;
};

SelfLookup no_self_lookup() {
  SelfLookup s;
  s.object = -1;
  s.origin = vec3(0.0f);
  s.t_min = 0.0f;
  s.facing = 1.0f;
  return s;
}

// The lookup of the object `hit` belongs to by a ray leaving it on the side of `g` (the geometric
// normal or its negation), moved `offset` off the surface.
SelfLookup self_lookup(SceneHit hit, vec3 g, float offset) {
  SelfLookup s;
  s.object = hit.object;
  s.origin = hit.position + offset * g;
  s.t_min = 2.0f * offset;
  s.facing = dot(hit.normal, g) >= 0.0f ? 1.0f : -1.0f;
  return s;
}

// The nearest hit of o + t d (world, d unit) on object k with t in (t_min, t_max): for meshes the
// field's first hit beyond t_min over its layers (a ray leaving the surface or inside the solid
// sees the surface beyond its origin), or the exact one of its BVH. A mesh that the ray leaves
// (self.object == k) is looked up as gf_trace_leaving does, from self.origin on the side
// self.facing: a path ray that starts object_epsilon(k, false) off the surface looks beyond 2 of
// them; a shadow ray, and a path ray from a point a lookup found (both start at self.origin),
// beyond self.t_min; `any_hit`: a shadow ray's lookup (gf_trace_from). Each lookup is called once
// here: the shader holds one copy of it.
SceneHit intersect_object(int k, vec3 o, vec3 d, float t_min, float t_max, SelfLookup self,
                          bool any_hit) {
  vec3 lo = (objects[k].to_object * vec4(o, 1.0f)).xyz;
  vec3 ld = (objects[k].to_object * vec4(d, 0.0f)).xyz;
  if (objects[k].kind.x == SHAPE_MESH) {
#if GF_BVH_MESHES
    if (GF_FIELD_MESHES == 0 || traced_by_bvh(k))  // a ray leaving the mesh starts off it
      return world_bvh_hit(k, bvh_mesh_hit(objects[k].image.z, lo, ld, t_min, t_max));
#endif
#if GF_FIELD_MESHES
    bool own = self.object == k;
    float from = own ? self.t_min : t_min;
    if (own && self.origin != o) from = 2.0f * object_epsilon(k, false, o);
    vec3 ls = (objects[k].to_object * vec4(self.origin, 1.0f)).xyz;
    select_mesh(k);
    return world_mesh_hit(k, gf_trace_from(lo, ld, from, t_max, ls, self.t_min, self.facing,
                                           SCENE_LOOKUP_MODE, own,
                                           any_hit && GF_FIELD_SHADOWS != 0));
#endif
    return scene_miss();
  }
  SceneHit h = scene_miss();
  ShapeHit s = intersect_shape(objects[k].kind.x, objects[k].shape, objects[k].size.xyz, lo, ld,
                               t_min, t_max);
  if (!s.hit) return h;
  h.hit = true;
  h.t = s.t;
  h.object = k;
  h.position = o + s.t * d;
  h.normal = normalize(transpose(mat3(objects[k].to_object)) * s.normal);
  h.uv = s.uv;
  h.self_offset = object_epsilon(k, false, h.position);
  return h;
}

// Albedo of object k's diffuse material at texture coordinates uv (gfield::texture_albedo).
vec3 object_albedo(int k, vec2 uv) {
  return texture_albedo(objects[k].kind.z, objects[k].color.rgb, objects[k].checker0,
                        objects[k].checker1, uv);
}

// Albedo of object k at a hit's uv (analytic: texture coordinates; mesh: geometry-image uv): a
// mesh with its own base colour (TEXTURE_MESH) multiplies its colour by the geometry image's
// albedo there.
vec3 hit_albedo(int k, vec2 uv) {
  if (objects[k].kind.x != SHAPE_MESH || objects[k].kind.z != TEXTURE_MESH ||
      objects[k].asset.w == 0)
    return object_albedo(k, uv);
  select_mesh(k);
  return objects[k].color.rgb * gs_image_albedo(uv);
}

// Where o + t d (world) enters object k's bounds (GpuObject.box_min/box_max, padded by 1e-3 of
// their diagonal: a field's hit lies on its geometry image, a hair off the mesh), t >= 0; GF_FAR
// when it misses them before t_max. A NaN (a ray along a face of the bounds) enters at 0: the
// test may keep an object it could skip, never skip one the ray meets.
float object_entry(int k, vec3 o, vec3 d, float t_max) {
  vec3 lo = (objects[k].to_object * vec4(o, 1.0f)).xyz;
  vec3 ld = (objects[k].to_object * vec4(d, 0.0f)).xyz;
  vec3 pad = vec3(1.0e-3f * distance(objects[k].box_min.xyz, objects[k].box_max.xyz));
  vec3 inv = 1.0f / ld;
  vec3 ta = (objects[k].box_min.xyz - pad - lo) * inv;
  vec3 tb = (objects[k].box_max.xyz + pad - lo) * inv;
  vec3 near = min(ta, tb);
  vec3 far = max(ta, tb);
  float enter = max(max(near.x, near.y), max(near.z, 0.0f));
  float leave = min(min(far.x, far.y), far.z);
  if (enter > leave || enter > t_max) return GF_FAR;
  return enter >= 0.0f ? enter : 0.0f;
}

// Whether trace_scene looks object k up for a ray (see there).
bool scene_candidate(int k, bool opaque_only, SelfLookup self, int inside) {
  if (opaque_only && objects[k].kind.y == MATERIAL_DIELECTRIC) return false;
  bool own = k == self.object && objects[k].kind.x == SHAPE_MESH;
  return !own || u_self_reflection || k == inside;
}

// trace_scene's order key of object k for a ray: where it enters the object's bounds (0 for the
// object it leaves, GF_FAR when it misses them before t_max), SCENE_SKIP when the object is not
// looked up.
const float SCENE_SKIP = -2.0f;
float scene_entry(int k, vec3 o, vec3 d, float t_max, bool opaque_only, SelfLookup self,
                  int inside) {
  if (!scene_candidate(k, opaque_only, self, inside)) return SCENE_SKIP;
  return k == self.object ? 0.0f : object_entry(k, o, d, t_max);
}

// The nearest hit of o + t d (world, d unit), t in (0, t_max), over all objects (as the reference
// tracer: a ray inside a dielectric meets what reaches into it too); `opaque_only` skips
// dielectrics (shadow rays: their first hit found is returned, as any hit blocks them). A mesh
// object that the ray leaves (self.object) looks itself up only with u_self_reflection, or when
// it is the dielectric the ray travels in (`inside`, -1: air). Objects are met in the order the
// ray enters their bounds (the object it leaves first), until the next one's bounds begin beyond
// the nearest hit found: one loop pass per object whose bounds the ray enters, not one per
// object, each with the one call of intersect_object (a shader runs a loop's body while any lane
// of a group needs it).
SceneHit trace_scene(vec3 o, vec3 d, float t_max, bool opaque_only, SelfLookup self, int inside) {
  SceneHit best = scene_miss();
  best.t = t_max;
  // The object met last and where the ray entered it: the next one comes after it in
  // (entry, index) order.
  int last = -1;
  float last_entry = -1.0f;
#if GF_CACHED_ENTRIES
  float entries[SCENE_CACHED_ENTRIES];
  for (int k = 0; k < u_object_count; k++)
    entries[k] = scene_entry(k, o, d, t_max, opaque_only, self, inside);
#endif
  for (int pass = 0; pass < u_object_count; pass++) {
    int next = -1;
    float next_entry = GF_FAR;
    for (int k = 0; k < u_object_count; k++) {
#if GF_CACHED_ENTRIES
      float entry = entries[k];
#else
      float entry = scene_entry(k, o, d, best.t, opaque_only, self, inside);
#endif
      if (entry == SCENE_SKIP) continue;
      bool after = entry > last_entry || (entry == last_entry && k > last);
      if (after && (entry < next_entry || next < 0)) {
        next = k;
        next_entry = entry;
      }
    }
    if (next < 0 || next_entry >= best.t) break;
    last = next;
    last_entry = next_entry;
    SelfLookup leaving = no_self_lookup();  // WebGL has no ?: of structs
    if (next == self.object && objects[next].kind.x == SHAPE_MESH) leaving = self;
    SceneHit h = intersect_object(next, o, d, 0.0f, best.t, leaving, opaque_only);
    if (h.hit && h.t < best.t) best = h;
    if (best.hit && opaque_only) break;  // a shadow ray: any hit blocks it
  }
  if (best.hit && !opaque_only && !best.has_albedo) best.albedo = hit_albedo(best.object, best.uv);
  return best;
}

// Light i as diffuse shading sees it from `hit` (seen along `incoming`): the radiance it adds,
// albedo * light * cos / d^2 (two sided), when nothing blocks the shadow ray `direction`,
// `distance` long, that starts at self.origin (diffuse and mirror objects block it); false when
// the light is behind the surface.
bool light_from(SceneHit hit, vec3 geometric_normal, vec3 incoming, int i, out vec3 direction,
                out float distance, out vec3 radiance, out SelfLookup self) {
  float facing = dot(incoming, geometric_normal) < 0.0f ? 1.0f : -1.0f;
  vec3 n = facing * hit.normal;
  vec3 g = facing * geometric_normal;
  bool point = lights[i].direction.w > 0.5f;
  vec3 l = -lights[i].direction.xyz;
  distance = GF_FAR;
  if (point) {
    l = lights[i].position.xyz - hit.position;
    distance = length(l);
    if (distance <= 0.0f) return false;
    l /= distance;
  }
  float cosine = dot(n, l);
  if (cosine <= 0.0f || dot(l, g) <= 0.0f) return false;
  direction = l;
  float falloff = point ? 1.0f / (distance * distance) : 1.0f;
  radiance = hit.albedo * lights[i].color.rgb * cosine * falloff;
  self = self_lookup(hit, g, shadow_epsilon(hit));
  return true;
}
