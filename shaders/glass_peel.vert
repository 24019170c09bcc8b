#version 450
// Depth peeling of the glass (Mukai et al. 2013, section 2.3 after Nakagawa et al. 2011): the
// glass's triangles (world space) with the number of the surface each belongs to.
layout(location = 0) in vec3 a_position;  // world
layout(location = 1) in float a_surface;  // slab: 0 the Z faces, 1 the X faces, 2 the Y faces;
                                          // hollow cylinder: 0 outer, 1 inner, 2 the rims

uniform mat4 u_view_projection;

layout(location = 0) flat out int v_surface;

void main() {
  v_surface = int(a_surface + 0.5f);
  gl_Position = u_view_projection * vec4(a_position, 1.0f);
}
