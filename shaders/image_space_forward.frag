#version 450
// Opaque surfaces for the image-space methods (the picture itself, the faces of a cube map, the
// nearby-geometry map of Davis & Wyman): diffuse shading, mirrors reflecting the environment.
// Alpha is the eye depth along u_forward (screen maps) or 1 (cube maps: coverage).
#include "lib/image_space.glsl"
#include "lib/image_space_surface.glsl"

uniform vec3 u_forward;
uniform bool u_alpha_is_coverage;

layout(location = 0) out vec4 o_color;

void main() {
  IsSurface s;
  if (!is_resolve_surface(s)) discard;
  vec3 incoming = normalize(s.position - u_eye);
  vec3 c = is_shade_surface(u_object, s.position, s.normal, incoming, s.albedo);
  o_color = vec4(c, u_alpha_is_coverage ? 1.0f : dot(s.position - u_eye, u_forward));
}
