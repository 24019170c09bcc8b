#version 450
// One object of the image-space methods: a mesh object's geometry-image grid, or the bounding
// box of an analytic shape (its fragments intersect the exact shape). Besides the world position
// and normal it carries d_n (Wyman 2005, read per vertex from the asset's thickness map) and the
// article's per-vertex refraction vector (Hurley, "Approximating Refraction"):
// R = -(alpha - 1)(N.E) N - E with E = eye - P, alpha the index (-1 gives the reflection vector).
layout(location = 0) in vec3 a_position;  // object space (analytic: the unit cube [-1, 1]^3)
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

layout(binding = 9) uniform sampler2DArray u_thickness;  // r = d_n (mesh units), layer = asset

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

void main() {
  vec4 world = u_to_world * vec4(a_position * u_proxy_half, 1.0f);
  v_position = world.xyz;
  v_normal = normalize(transpose(inverse(mat3(u_to_world))) * a_normal);
  v_uv = a_uv;
  v_thickness = 0.0f;
  if (u_thickness_layer >= 0) {
    ivec2 texel = clamp(ivec2(a_uv * float(u_gi_size)), ivec2(0), ivec2(u_gi_size - 1));
    float d = texelFetch(u_thickness, ivec3(texel, u_thickness_layer), 0).r;
    v_thickness = length(mat3(u_to_world) * (a_normal * d));
  }
  vec3 e = u_eye - world.xyz;
  v_hurley = -(u_alpha - 1.0f) * dot(v_normal, e) * v_normal - e;
  gl_Position = u_view_projection * world;
}
