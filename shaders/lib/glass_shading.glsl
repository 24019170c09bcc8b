// Diffuse shading for the glass method (runtime/methods/glass.cpp) as the reference tracer does
// it: albedo (plain, checker or colour chart) * (ambient + sum of lights * cos / d^2), two sided.
// The objects and lights are the scene's (the contract's buffers). Shadows of the first
// GLASS_SHADOWED_LIGHTS directional lights come from shadow maps of every opaque object (point
// lights cast none here).

#include "lib/contract.glsl"
#include "lib/textures.glsl"
#include "lib/objects.glsl"
layout(std430, binding = BUFFER_LIGHTS) readonly buffer Lights { GpuLight lights[]; };
uniform int u_object_count;
uniform int u_light_count;
uniform vec3 u_ambient;
uniform mat4 u_light_view_projection[GLASS_SHADOWED_LIGHTS];  // world -> shadow map clip space
layout(binding = UNIT_SHADOW_MAPS) uniform sampler2DArrayShadow u_shadow_maps;  // layer = light

// Fraction of light i reaching world point p (2 x 2 filtered shadow-map test).
float glass_light_visibility(int i, vec3 p, vec3 normal) {
  if (i >= GLASS_SHADOWED_LIGHTS || lights[i].direction.w > 0.5f) return 1.0f;
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
    if (lights[i].direction.w > 0.5f) {
      l = lights[i].position.xyz - p;
      float d = length(l);
      if (d <= 0.0f) continue;
      l /= d;
      falloff = 1.0f / (d * d);
    } else {
      l = -lights[i].direction.xyz;
    }
    float cosine = dot(n, l);
    if (cosine <= 0.0f || dot(l, g) <= 0.0f) continue;
    light_sum += lights[i].color.rgb * cosine * falloff * glass_light_visibility(i, p, g);
  }
  return albedo * light_sum;
}
