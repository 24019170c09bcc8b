#version 450
// Davis & Wyman 2007, "Interactive Refractions with Total Internal Reflection", pass 4: the view
// ray refracts at the front face; each bounce clips the ray to the view frustum (and to the
// refractor's box: the surface it seeks lies inside, so the search starts from a nearer end
// point) and intersects it by binary search with the back-face depth map and (first bounce, or
// always unless u_back_only_later) the front-face map, keeps the candidate more aligned with the
// ray, stops on a miss (both candidates misaligned), and at the hit either refracts out (below
// the critical angle) or reflects totally and bounces again, up to u_bounces intersections. The
// ray that leaves (or the one left after the last bounce) meets the nearby geometry (its depth
// map, same search) or an analytic background, then the environment.
#include "lib/image_space.glsl"
#include "lib/image_space_surface.glsl"

layout(binding = UNIT_BACK) uniform sampler2D u_back;    // back faces: normal, eye depth
layout(binding = UNIT_FRONT) uniform sampler2D u_front;   // front faces: normal, eye depth
layout(binding = UNIT_NEARBY) uniform sampler2D u_nearby;  // nearby geometry: colour, eye depth

uniform int u_bounces;            // internal intersections, 0..4 (more are allowed)
uniform int u_iterations_first;   // binary-search steps on the first transmitted ray (8)
uniform int u_iterations_later;   // on later rays (5)
uniform bool u_back_only_later;   // later bounces search the back-face map only
uniform int u_background;         // BACKGROUND_DEPTH_MAP or BACKGROUND_ANALYTIC
uniform int u_exit_iterations;    // steps in the nearby-geometry map
uniform float u_min_alignment;    // cosine below which a candidate is a miss
uniform float u_offset;           // start offset along rays (scene units)

// Where o + t d (world, o inside it) leaves the refractor's box, grown by 0.1%.
float box_exit(vec3 o, vec3 d) {
  vec3 margin = 1.0e-3f * (objects[u_object].box_max.xyz - objects[u_object].box_min.xyz);
  vec3 lo = objects[u_object].box_min.xyz - margin, hi = objects[u_object].box_max.xyz + margin;
  vec3 po = (objects[u_object].to_object * vec4(o, 1.0f)).xyz;
  vec3 inv = 1.0f / (objects[u_object].to_object * vec4(d, 0.0f)).xyz;
  vec3 t = max((lo - po) * inv, (hi - po) * inv);
  return max(0.0f, min(t.x, min(t.y, t.z)));
}

layout(location = 0) out vec4 o_color;

void main() {
  IsSurface s;
  if (!is_resolve_surface(s)) discard;
  float ior = objects[u_object].color.w;
  vec3 v = camera_direction();
  vec3 n1 = dot(v, s.normal) > 0.0f ? -s.normal : s.normal;
  vec3 o = s.position;
  vec3 d = gf_refract(v, n1, 1.0f / ior);
  if (dot(d, d) == 0.0f) d = gf_reflect(v, n1);
  for (int b = 0; b < u_bounces; b++) {
    int iterations = b == 0 ? u_iterations_first : u_iterations_later;
    float t_max = box_exit(o, d);
    MapHit best =
        is_search_depth_map(u_back, o, d, iterations, u_offset, u_refractor_depths, t_max);
    bool front = false;
    if (b == 0 || !u_back_only_later) {
      MapHit f =
          is_search_depth_map(u_front, o, d, iterations, u_offset, u_refractor_depths, t_max);
      if (f.found && (!best.found || f.alignment > best.alignment)) {
        best = f;
        front = true;
      }
    }
    if (!best.found || best.alignment < u_min_alignment) break;
    vec3 n = front ? texelFetch(u_front, best.texel, 0).xyz : texelFetch(u_back, best.texel, 0).xyz;
    if (dot(d, n) > 0.0f) n = -n;
    o = best.position;
    vec3 t = gf_refract(d, n, ior);
    if (dot(t, t) == 0.0f) {
      d = gf_reflect(d, n);  // total internal reflection: one more bounce
      continue;
    }
    d = t;
    break;
  }
  vec3 c = u_background == BACKGROUND_ANALYTIC
               ? is_exit_analytic(o, d)
               : is_exit_depth_map(u_nearby, o, d, u_exit_iterations, u_offset, u_min_alignment);
  o_color = vec4(c, 1.0f);
}
