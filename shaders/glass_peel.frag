#version 450
// One depth-peeling layer: the nearest glass surface behind the previous layer and in front of
// the scene (the opaque objects undisplaced). Writes the surface code (2 * surface + 1 when the
// surface faces away from the eye: the line leaves the glass there) and the window depth.
layout(location = 0) flat in int v_surface;

#include "lib/contract.glsl"

layout(binding = UNIT_PEEL_PREVIOUS) uniform sampler2D u_previous;  // x: code (-1: none), y: depth
// Layer 0 of the class images: a = the scene's window depth.
layout(binding = UNIT_CLASS_IMAGES) uniform sampler2DArray u_scene;
uniform bool u_first;

layout(location = 0) out vec4 o_layer;

void main() {
  if (gl_FragCoord.z >= texelFetch(u_scene, ivec3(ivec2(gl_FragCoord.xy), 0), 0).a) discard;
  if (!u_first) {
    vec4 previous = texelFetch(u_previous, ivec2(gl_FragCoord.xy), 0);
    if (previous.x < 0.0f || gl_FragCoord.z <= previous.y) discard;
  }
  float code = float(2 * v_surface + (gl_FrontFacing ? 0 : 1));
  o_layer = vec4(code, gl_FragCoord.z, 0.0f, 1.0f);
}
