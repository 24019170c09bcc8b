#version 450
// Shadow maps of the glass method: opaque objects seen from a directional light.
layout(location = 0) in vec3 a_position;  // object space

uniform mat4 u_to_world;
uniform mat4 u_light_view_projection;

void main() { gl_Position = u_light_view_projection * u_to_world * vec4(a_position, 1.0f); }
