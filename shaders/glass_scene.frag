#version 450
// The glass method's scene pass: diffuse shading at the undisplaced point, colour + depth out.
#include "lib/glass_shading.glsl"

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 3) in float v_valid;
layout(location = 4) in vec4 v_base;  // a mesh file's base colour and texture layer

uniform vec3 u_eye;
uniform int u_object;     // the object drawn: its material in objects[]
uniform bool u_smooth;    // interpolated normals (else the face's)

layout(location = 0) out vec4 o_color;  // rgb radiance, a = window depth of the drawn point

void main() {
  // A triangle with a vertex no path of this class reaches is dropped rather than smeared.
  if (v_valid < 0.999f) discard;
  vec3 g = normalize(cross(dFdx(v_world), dFdy(v_world)));
  vec3 n = u_smooth ? normalize(v_normal) : g;
  if (dot(g, n) < 0.0f) g = -g;
  GpuObject o = objects[u_object];
  vec3 albedo = o.kind.z == TEXTURE_MESH ? o.color.rgb * mesh_base_color(v_base, v_uv)
                                         : texture_albedo(o.kind.z, o.color.rgb, o.checker0,
                                                          o.checker1, v_uv);
  o_color = vec4(glass_shade(albedo, v_world, n, g, v_world - u_eye), gl_FragCoord.z);
}
