#version 450
// Wyman 2005, "An approximate image-space approach for interactive refraction" (Davis & Wyman's
// baseline [20]): refraction at the front face; the distance to the back is interpolated between
// d_v (back-face depth minus front depth along the view ray) and d_n (precomputed per vertex:
// the thickness map; analytic shapes: cast here) as d = (theta_t / theta_i) d_v +
// (1 - theta_t / theta_i) d_n; the back-face normal where that point projects gives ONE
// refraction out (beyond the critical angle the reflected direction leaves instead); the ray
// then meets the nearby geometry or the environment.
#include "lib/image_space.glsl"
#include "lib/image_space_surface.glsl"

layout(binding = UNIT_BACK) uniform sampler2D u_back;    // back faces: normal, eye depth
layout(binding = UNIT_NEARBY) uniform sampler2D u_nearby;  // nearby geometry: colour, eye depth

uniform int u_background;       // BACKGROUND_DEPTH_MAP or BACKGROUND_ANALYTIC
uniform int u_exit_iterations;  // binary-search steps in the nearby-geometry map
uniform float u_min_alignment;  // cosine below which a depth-map candidate is a miss
uniform float u_offset;         // start offset along rays (scene units)

layout(location = 0) out vec4 o_color;

vec3 leave(vec3 o, vec3 d) {
  if (u_background == BACKGROUND_ANALYTIC) return is_exit_analytic(o, d);
  return is_exit_depth_map(u_nearby, o, d, u_exit_iterations, u_offset, u_min_alignment);
}

void main() {
  IsSurface s;
  if (!is_resolve_surface(s)) discard;
  int k = u_object;
  float ior = objects[k].color.w;
  vec3 v = camera_direction();
  vec3 n1 = dot(v, s.normal) > 0.0f ? -s.normal : s.normal;
  vec3 t1 = gf_refract(v, n1, 1.0f / ior);
  if (dot(t1, t1) == 0.0f) {
    o_color = vec4(leave(s.position, gf_reflect(v, n1)), 1.0f);
    return;
  }
  float d_n = v_thickness;
  if (objects[k].kind.x != SHAPE_MESH) {
    ShapeHit h = is_intersect_analytic(k, s.position, -n1, u_offset, GF_FAR);
    d_n = h.hit ? h.t : 0.0f;
  }
  ivec2 size = textureSize(u_back, 0);
  ivec2 here = clamp(ivec2(gl_FragCoord.xy / u_image_size * vec2(size)), ivec2(0), size - 1);
  float z_back = texelFetch(u_back, here, 0).a;
  float d_v = z_back >= IS_FAR ? d_n
                               : max(z_back - is_eye_depth(s.position), 0.0f) /
                                     dot(v, u_camera_forward);
  float theta_i = acos(clamp(-dot(v, n1), -1.0f, 1.0f));
  float theta_t = acos(clamp(-dot(t1, n1), -1.0f, 1.0f));
  float ratio = theta_i > 1.0e-4f ? theta_t / theta_i : 1.0f / ior;
  vec3 p2 = s.position + (ratio * d_v + (1.0f - ratio) * d_n) * t1;
  vec3 q = is_project(p2);
  vec3 d = t1;
  if (all(greaterThanEqual(q.xy, vec2(0.0f))) && all(lessThan(q.xy, vec2(1.0f)))) {
    vec4 back = texelFetch(u_back, ivec2(q.xy * vec2(size)), 0);
    if (back.a < IS_FAR) {
      vec3 n2 = dot(t1, back.xyz) > 0.0f ? -back.xyz : back.xyz;
      vec3 t2 = gf_refract(t1, n2, ior);
      d = dot(t2, t2) == 0.0f ? gf_reflect(t1, n2) : t2;
    }
  }
  o_color = vec4(leave(p2, d), 1.0f);
}
