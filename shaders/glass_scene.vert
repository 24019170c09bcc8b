#version 450
// The glass method's scene pass (Mukai et al. 2013): every opaque object drawn once per
// refraction class, each vertex moved to where the eye sees it through the glass along that
// class's path (shaders/lib/glass_displacement.glsl); shading uses the undisplaced point.
#include "lib/glass_displacement.glsl"

layout(location = 0) in vec3 a_position;  // object space
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
layout(location = 3) in vec4 a_base;  // a mesh file's base colour and texture layer

uniform mat4 u_to_world;
uniform mat3 u_normal_to_world;
uniform mat4 u_view_projection;
uniform vec3 u_eye;          // world
uniform int u_glass;         // 0: no displacement, 1: plate, 2: hollow cylinder
uniform float u_ior;         // glass index relative to air
// Plate (world): the pair of parallel faces of this class.
uniform vec3 u_plate_centre;
uniform vec3 u_plate_normal;
uniform float u_plate_thickness;
// Hollow cylinder: object space maps (uniform scale) and radii; the class's path (GD_PATH_*).
uniform mat4 u_cylinder_to_object;
uniform mat4 u_cylinder_to_world;
uniform float u_outer_radius;
uniform float u_inner_radius;
uniform int u_path;

layout(location = 0) out vec3 v_world;   // undisplaced
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec2 v_uv;
layout(location = 3) out float v_valid;  // 1: placed; 0: no path of the class reaches it
layout(location = 4) out vec4 v_base;

// True when the segment from the eye to q (object space) crosses the infinite outer cylinder:
// then q is behind glass along the straight line and must be reached by a refracted path.
bool glass_behind_cylinder(vec3 e, vec3 q) {
  vec3 d = q - e;
  float a = d.x * d.x + d.z * d.z;
  if (a <= 0.0f) return false;
  float t = clamp(-(e.x * d.x + e.z * d.z) / a, 0.0f, 1.0f);
  vec3 c = e + t * d;
  return c.x * c.x + c.z * c.z < u_outer_radius * u_outer_radius;
}

void main() {
  vec3 world = (u_to_world * vec4(a_position, 1.0f)).xyz;
  vec3 seen = world;
  float valid = 1.0f;
  if (u_glass == 1) {
    seen = gd_plate_displace(u_eye, world, u_plate_centre, u_plate_normal, u_plate_thickness,
                             u_ior);
  } else if (u_glass == 2) {
    vec3 q = (u_cylinder_to_object * vec4(world, 1.0f)).xyz;
    vec3 e = (u_cylinder_to_object * vec4(u_eye, 1.0f)).xyz;
    float rq = sqrt(q.x * q.x + q.z * q.z);
    bool interior = rq < u_inner_radius;
    bool in_wall = !interior && rq <= u_outer_radius;
    int path = u_path;
    // Points inside the glass are seen through the front wall wherever the line crosses it;
    // through the verge and from the open top they are seen directly.
    if (interior) path = (path == GD_PATH_BOTH_WALLS || path == GD_PATH_FRONT_WALL)
                             ? GD_PATH_FRONT_WALL : -1;
    if (in_wall) path = -1;
    // Outside the glass, every point a path through both walls or the verge reaches is moved
    // there (near the inner silhouette such paths bend far, to points whose straight line misses
    // the cylinder: leaving those in place would stretch triangles across the class's image);
    // the walls' own paths take the points whose straight line crosses the cylinder.
    bool bending = path == GD_PATH_BOTH_WALLS || path == GD_PATH_VERGE;
    if (path >= 0 && (interior || bending || glass_behind_cylinder(e, q))) {
      bool ok = false;
      vec3 s = gd_cylinder_displace(path, u_outer_radius, u_inner_radius, u_ior, e, q, ok);
      if (ok) {
        seen = (u_cylinder_to_world * vec4(s, 1.0f)).xyz;
      } else {
        valid = 0.0f;
      }
    }
  }
  v_world = world;
  v_normal = u_normal_to_world * a_normal;
  v_uv = a_uv;
  v_base = a_base;
  v_valid = valid;
  gl_Position = u_view_projection * vec4(seen, 1.0f);
}
