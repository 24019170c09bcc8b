// Diffuse shading for the glass method (runtime/methods/glass.cpp) as the reference tracer does
// it: albedo (plain, checker or colour chart) * (ambient + sum of lights * cos / d^2), two sided.
// Shadows of directional lights come from shadow maps of every opaque object (point lights cast
// none here).

#define GLASS_MAX_LIGHTS 4
#define GLASS_TEXTURE_NONE 0
#define GLASS_TEXTURE_CHECKER 1
#define GLASS_TEXTURE_COLOR_CHART 2

uniform int u_light_count;
uniform vec4 u_light_direction[GLASS_MAX_LIGHTS];  // xyz: the way it travels; w: 1 point light
uniform vec3 u_light_position[GLASS_MAX_LIGHTS];
uniform vec3 u_light_color[GLASS_MAX_LIGHTS];       // colour * intensity
uniform mat4 u_light_view_projection[GLASS_MAX_LIGHTS];  // world -> shadow map clip space
uniform vec3 u_ambient;
layout(binding = 6) uniform sampler2DArrayShadow u_shadow_maps;  // layer = light

// gfield::texture_albedo.
vec3 glass_albedo(int texture_type, vec3 color, vec4 checker0, vec4 checker1, vec2 uv) {
  if (texture_type == GLASS_TEXTURE_CHECKER) {
    int cu = int(floor(uv.x * checker0.w));
    int cv = int(floor(uv.y * checker1.w));
    return ((cu + cv) & 1) == 0 ? checker0.rgb : checker1.rgb;
  }
  if (texture_type == GLASS_TEXTURE_COLOR_CHART) {
    const vec3 patches[24] = vec3[](
        vec3(115, 82, 68), vec3(194, 150, 130), vec3(98, 122, 157), vec3(87, 108, 67),
        vec3(133, 128, 177), vec3(103, 189, 170), vec3(214, 126, 44), vec3(80, 91, 166),
        vec3(193, 90, 99), vec3(94, 60, 108), vec3(157, 188, 64), vec3(224, 163, 46),
        vec3(56, 61, 150), vec3(70, 148, 73), vec3(175, 54, 60), vec3(231, 199, 31),
        vec3(187, 86, 149), vec3(8, 133, 161), vec3(243, 243, 242), vec3(200, 200, 200),
        vec3(160, 160, 160), vec3(122, 122, 121), vec3(85, 85, 85), vec3(52, 52, 52));
    float u = clamp(uv.x, 0.0f, 1.0f) * 6.0f;
    float v = clamp(1.0f - uv.y, 0.0f, 1.0f) * 4.0f;
    int column = min(int(u), 5);
    int row = min(int(v), 3);
    float fu = u - float(column);
    float fv = v - float(row);
    const float gap = 0.08f;
    if (fu < gap || fu > 1.0f - gap || fv < gap || fv > 1.0f - gap) return vec3(0.01f);
    vec3 c = patches[row * 6 + column] / 255.0f;
    return mix(c / 12.92f, pow((c + 0.055f) / 1.055f, vec3(2.4f)), greaterThan(c, vec3(0.04045f)));
  }
  return color;
}

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
