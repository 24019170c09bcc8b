// The geometry-field renderer's shading of one pixel (Li et al. 2006, section 3.2) over the
// G-buffer of first hits, shared by its two passes (field_trace.frag, a full-screen fragment
// pass; field_trace.comp, a compute dispatch: the same code, so the same picture):
//   1. the eye ray of the pixel; 2. at a reflective hit the reflection ray; 3. local shading of
//   diffuse hits; 4. TraceRay: for every object, the ray in its unit cube, clipped, entry/exit ->
//   field lookup -> geometry-image position, the nearest hit, shaded and blended, recursively
//   up to u_max_depth.
// Recursion becomes a small stack of weighted rays. Dielectrics (the paper's "generalised to
// refraction") split into the Fresnel-weighted reflection and the refraction; inside a mesh the
// exit is the field's first hit beyond the ray's origin (its layers hold the hits behind the
// entry), and a ray leaving a non-convex object looks the object up again beyond its origin (the
// air gap, then the next part); total internal reflection keeps the ray inside. Shading follows
// the reference tracer (reference_tracer.cpp).
#include "lib/scene.glsl"
#include "lib/optics.glsl"
#include "lib/camera.glsl"

layout(binding = UNIT_GBUFFER_POSITION) uniform sampler2D u_g_position;    // xyz world, w object
layout(binding = UNIT_GBUFFER_NORMAL) uniform sampler2D u_g_normal;        // xyz shading normal, w u
layout(binding = UNIT_GBUFFER_GEOMETRIC) uniform sampler2D u_g_geometric;  // xyz geometric, w v
layout(binding = UNIT_GBUFFER_ALBEDO) uniform sampler2D u_g_albedo;        // rgb albedo
uniform int u_max_depth;      // reflections/refractions after the camera ray (as gfield render)
uniform float u_min_weight;   // branches below this path weight are not traced
uniform int u_max_rays;       // secondary rays per pixel at most

// Rays waiting to be traced, last in first out: path rays (reflections, refractions) and the
// shadow rays of diffuse hits. Every ray is traced by the one call of trace_scene in
// trace_pixel(), and every hit shaded by the one call of shade_hit: each is inlined once (see
// gf_trace_from).
#define STACK_SIZE 16

struct PathRay {
  vec3 origin;
  vec3 direction;
  vec3 weight;      // path rays: the path's weight; shadow rays: the radiance the light adds
  float t_max;      // shadow rays: the distance to the light
  bool shadow;
  int depth;
  int inside;       // the dielectric object the ray travels in, -1 for air
  SelfLookup self;  // the lookup of the object it leaves
};

PathRay stack_rays[STACK_SIZE];
int stack_count = 0;

void push(PathRay r) {
  if (stack_count >= STACK_SIZE) return;
  stack_rays[stack_count] = r;
  stack_count++;
}

// A ray leaving `hit` on the side of `g` (the geometric normal, or its negation).
void push_ray(SceneHit hit, vec3 g, vec3 direction, vec3 weight, int depth, int inside) {
  if (max(weight.r, max(weight.g, weight.b)) < u_min_weight) return;
  PathRay r;
  r.origin = hit.position + object_epsilon(hit.object, false, hit.position) * g;
  r.direction = normalize(direction);
  r.weight = weight;
  r.t_max = GF_FAR;
  r.shadow = false;
  r.depth = depth;
  r.inside = inside;
  r.self = self_lookup(hit, g, hit.self_offset);
  push(r);
}

// Diffuse shading of `hit` seen along `ray` (as the reference tracer's): the ambient part now,
// each light's part by a shadow ray.
void shade_diffuse(SceneHit hit, vec3 geometric, PathRay ray, inout vec3 radiance) {
  radiance += ray.weight * hit.albedo * u_ambient;
  for (int i = 0; i < u_light_count; i++) {
    PathRay s;
    if (!light_from(hit, geometric, ray.direction, i, s.direction, s.t_max, s.weight, s.self))
      continue;
    s.origin = s.self.origin;
    s.weight *= ray.weight;
    s.shadow = true;
    s.depth = ray.depth;
    s.inside = -1;
    push(s);
  }
}

// What a ray sees at a hit: diffuse shading is added to `radiance` (its lights by shadow rays);
// mirrors and dielectrics push their continuing rays.
void shade_hit(SceneHit hit, vec3 geometric, PathRay ray, inout vec3 radiance) {
  int k = hit.object;
  int material = objects[k].kind.y;
  vec3 d = ray.direction;
  if (material == MATERIAL_DIFFUSE) {
    shade_diffuse(hit, geometric, ray, radiance);
    return;
  }
  bool front = dot(d, geometric) < 0.0f;
  vec3 n = front ? hit.normal : -hit.normal;
  vec3 g = front ? geometric : -geometric;
  if (material == MATERIAL_MIRROR) {
    if (ray.depth >= u_max_depth) return;
    vec3 r = gf_reflect(d, n);
    if (dot(r, g) <= 0.0f) r = gf_reflect(d, g);
    push_ray(hit, g, r, ray.weight * objects[k].color.rgb, ray.depth + 1, -1);
    return;
  }
  // Dielectric: the segment just travelled was inside when the surface is hit from the back.
  vec3 weight = ray.weight;
  if (!front) weight *= exp(-objects[k].absorption.rgb * hit.t);
  if (ray.depth >= u_max_depth) return;
  float ior = objects[k].color.w;
  float n1 = front ? 1.0f : ior;
  float n2 = front ? ior : 1.0f;
  float r = fresnel_dielectric(-dot(d, n), n1, n2);
  vec3 reflected = gf_reflect(d, n);
  vec3 transmitted = gf_refract(d, n, n1 / n2);
  bool tir = r >= 1.0f || dot(transmitted, transmitted) == 0.0f;
  int outside_of = front ? -1 : k;  // where the reflected ray travels
  if (tir) {
    push_ray(hit, g, reflected, weight, ray.depth + 1, outside_of);
    return;
  }
  push_ray(hit, g, reflected, weight * r, ray.depth + 1, outside_of);
  push_ray(hit, -g, transmitted, weight * (1.0f - r), ray.depth + 1, front ? k : -1);
}

// The pixel's colour (linear radiance, alpha 1) and hits (first hit object, secondary rays
// traced, 0, 0). `pixel` counts from the bottom left, as gl_FragCoord.
void trace_pixel(ivec2 pixel, out vec4 color, out vec4 hits) {
  vec4 g_position = texelFetch(u_g_position, pixel, 0);
  vec4 g_normal = texelFetch(u_g_normal, pixel, 0);
  vec4 g_geometric = texelFetch(u_g_geometric, pixel, 0);
  int first = int(g_position.w);
  PathRay camera;
  camera.origin = u_camera_position;
  camera.direction = camera_direction_at(vec2(pixel) + 0.5f);
  camera.weight = vec3(1.0f);
  camera.t_max = GF_FAR;
  camera.shadow = false;
  camera.depth = 0;
  camera.inside = -1;
  camera.self = no_self_lookup();
  vec3 radiance = vec3(0.0f);
  int traced = 0;
  // The camera ray's hit is the G-buffer's; then rays from the stack, each traced.
  PathRay ray = camera;
  SceneHit hit = scene_miss();
  vec3 geometric = vec3(0.0f);
  if (first >= 0) {
    hit.hit = true;
    hit.object = first;
    hit.position = g_position.xyz;
    hit.t = distance(u_camera_position, g_position.xyz);
    hit.normal = g_normal.xyz;
    hit.uv = vec2(g_normal.w, g_geometric.w);
    hit.albedo = texelFetch(u_g_albedo, pixel, 0).rgb;
    hit.has_albedo = true;
    hit.self_offset = object_epsilon(first, true, hit.position);
    geometric = g_geometric.xyz;
  }
  for (bool traced_ray = false;; traced_ray = true) {
    if (traced_ray) {
      if (stack_count == 0) break;
      stack_count--;
      ray = stack_rays[stack_count];
      if (!ray.shadow) {
        if (traced >= u_max_rays) continue;  // the shadow rays below it are still traced
        traced++;
      }
      hit = trace_scene(ray.origin, ray.direction, ray.t_max, ray.shadow, ray.self, ray.inside);
      geometric = hit.normal;
    }
    if (ray.shadow) {
      if (!hit.hit) radiance += ray.weight;
    } else if (!hit.hit) {
      radiance += ray.weight * environment_radiance(ray.direction);
    } else {
      shade_hit(hit, geometric, ray, radiance);
    }
  }
  WORK_ADD(WORK_RAYS, traced);
  work_flush();
  color = vec4(radiance, 1.0f);
  hits = vec4(float(first), float(traced), 0.0f, 0.0f);
}
