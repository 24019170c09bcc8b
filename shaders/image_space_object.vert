#version 450
// One object of the image-space methods: a mesh object's parameterised mesh (refractors: uv =
// geometry-image uv) or mesh file (opaque objects: its own uvs and base colour), or the bounding
// box of an analytic shape (its fragments intersect the exact shape). Besides the world position
// and normal it carries d_n (Wyman 2005, read per vertex from the asset's thickness map) and the
// article's per-vertex refraction vector (Hurley, "Approximating Refraction"):
// R = -(alpha - 1)(N.E) N - E with E = eye - P, alpha the index (-1 gives the reflection vector).
layout(location = 0) in vec3 a_position;  // object space (analytic: the unit cube [-1, 1]^3)
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_base;  // a mesh file's base colour and texture layer

#include "lib/contract.glsl"

layout(binding = UNIT_THICKNESS) uniform sampler2DArray u_thickness;  // r = d_n (mesh units), layer = asset

uniform mat4 u_to_world;
uniform mat4 u_view_projection;
uniform vec3 u_proxy_half;     // analytic: half extents of the shape's bounds; mesh: 1
uniform int u_thickness_layer; // -1: no thickness map
uniform int u_gi_size;  // n of the geometry image
uniform vec3 u_eye;            // the viewpoint of this pass
uniform float u_alpha;         // Hurley's index (cube-map method)

layout(location = 0) out vec3 v_position;  // world
layout(location = 1) out vec3 v_normal;    // world
layout(location = 2) out vec2 v_uv;
layout(location = 3) out float v_thickness;  // world d_n
layout(location = 4) out vec3 v_hurley;      // per-vertex refraction vector (unnormalised)
layout(location = 5) out vec4 v_base;

// d_n at geometry-image uv `uv` (texel centres at (i + 0.5) / n): bilinear over the four nearest
// texels that hold a surface (d > 0; padding holds 0), so that a corner on a chart's border reads
// its own chart; the nearest of the 3x3 texels around it when none of the four does.
float thickness_at(vec2 uv) {
  vec2 f = uv * float(u_gi_size) - 0.5f;
  ivec2 base = ivec2(floor(f));
  vec2 w = f - vec2(base);
  float sum = 0.0f, weight = 0.0f;
  for (int j = 0; j < 2; j++) {
    for (int i = 0; i < 2; i++) {
      ivec2 t = clamp(base + ivec2(i, j), ivec2(0), ivec2(u_gi_size - 1));
      float d = texelFetch(u_thickness, ivec3(t, u_thickness_layer), 0).r;
      float k = (i == 0 ? 1.0f - w.x : w.x) * (j == 0 ? 1.0f - w.y : w.y);
      if (d > 0.0f) {
        sum += k * d;
        weight += k;
      }
    }
  }
  if (weight > 0.0f) return sum / weight;
  ivec2 centre = ivec2(uv * float(u_gi_size));
  float best = 0.0f, best_distance = 1.0e30f;
  for (int j = -1; j <= 1; j++) {
    for (int i = -1; i <= 1; i++) {
      ivec2 t = clamp(centre + ivec2(i, j), ivec2(0), ivec2(u_gi_size - 1));
      float d = texelFetch(u_thickness, ivec3(t, u_thickness_layer), 0).r;
      float distance = length(vec2(t) + 0.5f - uv * float(u_gi_size));
      if (d > 0.0f && distance < best_distance) {
        best = d;
        best_distance = distance;
      }
    }
  }
  return best;
}

void main() {
  vec4 world = u_to_world * vec4(a_position * u_proxy_half, 1.0f);
  v_position = world.xyz;
  v_normal = normalize(transpose(inverse(mat3(u_to_world))) * a_normal);
  v_uv = a_uv;
  v_base = a_base;
  v_thickness = 0.0f;
  if (u_thickness_layer >= 0) {
    v_thickness = length(mat3(u_to_world) * (a_normal * thickness_at(a_uv)));
  }
  vec3 e = u_eye - world.xyz;
  v_hurley = -(u_alpha - 1.0f) * dot(v_normal, e) * v_normal - e;
  gl_Position = u_view_projection * world;
}
