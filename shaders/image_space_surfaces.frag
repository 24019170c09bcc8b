#version 450
// Davis & Wyman 2007 passes 1 and 2 (and Wyman 2005's back-face pass): the refractors' back-
// facing (u_facing = -1) or front-facing (u_facing = 1) normals and depths, nearest first.
// Output: xyz = world normal out of the solid, w = eye depth (IS_FAR where nothing is drawn).
#include "lib/image_space.glsl"
#include "lib/image_space_surface.glsl"

layout(location = 0) out vec4 o_surface;

void main() {
  IsSurface s;
  if (!is_resolve_surface(s)) discard;
  o_surface = vec4(s.normal, is_eye_depth(s.position));
}
