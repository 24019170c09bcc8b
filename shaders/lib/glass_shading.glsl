// Diffuse shading for the glass method (runtime/methods/glass.cpp) as the reference tracer does
// it: albedo (plain, checker or colour chart) * (ambient + sum of lights * cos / d^2), two sided.
// Shadows of directional lights come from shadow maps of every opaque object (point lights cast
// none here).

#include "lib/textures.glsl"

#define GLASS_MAX_LIGHTS 4

uniform int u_light_count;
uniform vec4 u_light_direction[GLASS_MAX_LIGHTS];  // xyz: the way it travels; w: 1 point light
uniform vec3 u_light_position[GLASS_MAX_LIGHTS];
uniform vec3 u_light_color[GLASS_MAX_LIGHTS];       // colour * intensity
uniform mat4 u_light_view_projection[GLASS_MAX_LIGHTS];  // world -> shadow map clip space
uniform vec3 u_ambient;
layout(binding = 6) uniform sampler2DArrayShadow u_shadow_maps;  // layer = light

// Fraction of light i reaching world point p (2 x 2 filtered shadow-map test).
float glass_light_visibility(int i, vec3 p, vec3 normal) {
  if (u_light_direction[i].w > 0.5f) return 1.0f;
  vec4 clip = u_light_view_projection[i] * vec4(p, 1.0f);
  vec3 ndc = clip.xyz / clip.w;
  vec3 coord = 0.5f * ndc + 0.5f;
  if (any(lessThan(coord.xy, vec2(0.0f))) || any(greaterThan(coord.xy, vec2(1.0f)))) return 1.0f;
  return texture(u_shadow_maps, vec4(coord.xy, float(i), coord.z));
}

// Radiance leaving a diffuse point p with shading normal n and geometric normal g (world, unit),
// seen along `incoming`.
vec3 glass_shade(vec3 albedo, vec3 p, vec3 n, vec3 g, vec3 incoming) {
  float facing = dot(incoming, g) < 0.0f ? 1.0f : -1.0f;
  n = facing * n;
  g = facing * g;
  vec3 light_sum = u_ambient;
  for (int i = 0; i < u_light_count; i++) {
    vec3 l;
    float falloff = 1.0f;
    if (u_light_direction[i].w > 0.5f) {
      l = u_light_position[i] - p;
      float d = length(l);
      if (d <= 0.0f) continue;
      l /= d;
      falloff = 1.0f / (d * d);
    } else {
      l = -u_light_direction[i].xyz;
    }
    float cosine = dot(n, l);
    if (cosine <= 0.0f || dot(l, g) <= 0.0f) continue;
    light_sum += u_light_color[i] * cosine * falloff * glass_light_visibility(i, p, g);
  }
  return albedo * light_sum;
}
