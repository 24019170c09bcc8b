#version 450
// G-buffer of the first hits: position + object, shading normal + u, geometric normal + v,
// albedo (a mesh's own base colour through its own uvs and texture).
#include "lib/objects.glsl"
#include "lib/shapes.glsl"
#include "lib/textures.glsl"

layout(location = 0) in vec3 v_position;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 3) in vec4 v_base;

uniform int u_object;
uniform int u_shape;        // SHAPE_*; SHAPE_MESH rasterises the geometry-image grid
uniform vec4 u_shape_params;  // radius, height, thickness
uniform vec3 u_shape_size;
uniform mat4 u_to_object;
uniform mat4 u_to_world;
uniform mat4 u_view_projection;
uniform vec3 u_camera_position;

layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_geometric;
layout(location = 3) out vec4 o_albedo;

void main() {
  vec3 position = v_position;
  vec3 normal;
  vec3 geometric;
  vec2 uv = v_uv;
  GpuObject o = objects[u_object];
  vec3 albedo = o.color.rgb;
  if (u_shape == SHAPE_MESH) {
    if (o.kind.z == TEXTURE_MESH) albedo *= mesh_base_color(v_base, v_uv);
    normal = normalize(v_normal);
    geometric = normalize(cross(dFdx(v_position), dFdy(v_position)));
    if (dot(geometric, normal) < 0.0f) geometric = -geometric;
    gl_FragDepth = gl_FragCoord.z;
  } else {
    // The eye ray through this fragment against the exact shape.
    vec3 d = normalize(v_position - u_camera_position);
    vec3 lo = (u_to_object * vec4(u_camera_position, 1.0f)).xyz;
    vec3 ld = (u_to_object * vec4(d, 0.0f)).xyz;
    ShapeHit h = intersect_shape(u_shape, u_shape_params, u_shape_size, lo, ld, 0.0f, GF_FAR);
    if (!h.hit) discard;
    position = u_camera_position + h.t * d;
    normal = normalize(transpose(mat3(u_to_object)) * h.normal);
    geometric = normal;
    uv = h.uv;
    albedo = texture_albedo(o.kind.z, o.color.rgb, o.checker0, o.checker1, uv);
    vec4 clip = u_view_projection * vec4(position, 1.0f);
    gl_FragDepth = clamp(0.5f * clip.z / clip.w + 0.5f, 0.0f, 1.0f);
  }
  o_position = vec4(position, float(u_object));
  o_normal = vec4(normal, uv.x);
  o_geometric = vec4(geometric, uv.y);
  o_albedo = vec4(albedo, 1.0f);
}
