#version 450
// Rasterisation of one object into the G-buffer: a mesh object's mesh file (its own uvs and
// base colour), or the bounding box of an analytic shape (its fragments intersect the exact
// shape).
layout(location = 0) in vec3 a_position;  // object space (analytic: the unit cube [-1, 1]^3)
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_base;      // mesh: base colour and texture layer

uniform mat4 u_to_world;
uniform mat4 u_view_projection;
uniform vec3 u_proxy_half;  // analytic: half extents of the shape's bounds; mesh: 1

layout(location = 0) out vec3 v_position;  // world
layout(location = 1) out vec3 v_normal;    // world
layout(location = 2) out vec2 v_uv;
layout(location = 3) out vec4 v_base;

void main() {
  vec4 world = u_to_world * vec4(a_position * u_proxy_half, 1.0f);
  v_position = world.xyz;
  v_normal = transpose(inverse(mat3(u_to_world))) * a_normal;
  v_uv = a_uv;
  v_base = a_base;
  gl_Position = u_view_projection * world;
}
