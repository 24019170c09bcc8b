#version 450
// Hurley, "Approximating Refraction": a refractor (or a mirror) looks its surroundings up in a
// cube map rendered from its centre. Dielectrics bend the view ray once, by the article's
// per-vertex vector R = -(alpha - 1)(N.E) N - E interpolated over the triangle, or per fragment by
// Snell's law; beyond the critical angle (index < 1) they reflect instead, and optionally blend
// reflection and refraction by Fresnel. Mirrors, and every object in `envmap` mode, use the
// reflection vector (the article's alpha = -1): the classic environment-mapped reflection.
// The cube map holds the nearby objects (alpha = coverage); where it is empty the environment is
// evaluated exactly along the looked-up direction.
#include "lib/image_space.glsl"
#include "lib/image_space_surface.glsl"

layout(binding = UNIT_CUBE) uniform samplerCube u_cube;

uniform bool u_reflect_only;  // envmap: every object reflects
uniform bool u_per_vertex;    // the article's interpolated vector instead of per-fragment Snell
uniform bool u_fresnel;       // blend in the Fresnel-weighted reflection

layout(location = 0) out vec4 o_color;

// What the cube map shows along the unit direction d.
vec3 cube_radiance(vec3 d) {
  vec4 c = texture(u_cube, d);
  return c.rgb + (1.0f - c.a) * environment_radiance(d);
}

void main() {
  IsSurface s;
  if (!is_resolve_surface(s)) discard;
  vec3 v = camera_direction();
  vec3 n = dot(v, s.normal) > 0.0f ? -s.normal : s.normal;
  int k = u_object;
  vec3 reflected = cube_radiance(normalize(gf_reflect(v, n)));
  if (u_reflect_only || objects[k].kind.y == MATERIAL_MIRROR) {
    vec3 tint = objects[k].kind.y == MATERIAL_MIRROR ? objects[k].color.rgb : vec3(1.0f);
    o_color = vec4(tint * reflected, 1.0f);
    return;
  }
  float ior = objects[k].color.w;
  float cos_i = clamp(-dot(v, n), 0.0f, 1.0f);
  vec3 t;
  bool total_reflection;
  if (u_per_vertex) {
    t = normalize(v_hurley);
    total_reflection = ior < 1.0f && 1.0f - cos_i * cos_i > ior * ior;
  } else {
    // Index 1 does not bend the ray: v itself, not gf_refract()'s rounding of it.
    vec3 r = gf_refract(v, n, 1.0f / ior);
    total_reflection = dot(r, r) == 0.0f;
    t = ior == 1.0f ? v : total_reflection ? r : normalize(r);
  }
  vec3 c = total_reflection ? reflected : cube_radiance(t);
  if (u_fresnel && !total_reflection) c = mix(c, reflected, fresnel_dielectric(cos_i, 1.0f, ior));
  o_color = vec4(c, 1.0f);
}
