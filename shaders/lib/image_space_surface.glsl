// The surface under a fragment of an object drawn by shaders/image_space_object.vert: a mesh's
// interpolated normal, or the exact analytic shape along the ray from u_eye (its first hit for
// front faces, its last one for back faces), with gl_FragDepth set to match.

layout(location = 0) in vec3 v_position;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec2 v_uv;
layout(location = 3) in float v_thickness;
layout(location = 4) in vec3 v_hurley;
layout(location = 5) in vec4 v_base;

uniform int u_object;
uniform mat4 u_view_projection;
uniform vec3 u_eye;
uniform int u_facing;  // 1: front faces only, -1: back faces only, 0: the nearest surface

struct IsSurface {
  vec3 position;  // world
  vec3 normal;    // world, unit, out of the solid
  vec2 uv;
  vec3 albedo;    // diffuse: the albedo there (a mesh file's own base colour through its uvs)
  bool front;     // faces u_eye
};

// False when the fragment shows no surface of the wanted facing (the caller discards).
bool is_resolve_surface(out IsSurface s) {
  vec3 geometric = cross(dFdx(v_position), dFdy(v_position));
  s.position = v_position;
  s.normal = normalize(v_normal);
  s.uv = v_uv;
  int k = u_object;
  s.albedo = objects[k].color.rgb;
  if (objects[k].kind.x == SHAPE_MESH) {
    if (objects[k].kind.z == TEXTURE_MESH) s.albedo *= mesh_base_color(v_base, v_uv);
    if (dot(geometric, s.normal) < 0.0f) geometric = -geometric;
    s.front = dot(geometric, v_position - u_eye) < 0.0f;
    gl_FragDepth = gl_FragCoord.z;
  } else {
    vec3 d = normalize(v_position - u_eye);
    ShapeHit h = is_intersect_analytic(k, u_eye, d, 0.0f, GF_FAR);
    if (!h.hit) return false;
    s.front = true;
    if (u_facing < 0) {
      // The last surface along the eye ray (at most 4 crossings: the hollow cylinder).
      ShapeHit last = h;
      for (int i = 0; i < 3; i++) {
        ShapeHit next = is_intersect_analytic(k, u_eye, d, last.t + 1.0e-5f * u_scene_extent,
                                              GF_FAR);
        if (!next.hit) break;
        last = next;
      }
      if (last.t == h.t) return false;
      h = last;
      s.front = false;
    }
    s.position = u_eye + h.t * d;
    s.normal = h.normal;
    s.uv = h.uv;
    s.albedo = object_albedo(k, h.uv);
    vec4 clip = u_view_projection * vec4(s.position, 1.0f);
    gl_FragDepth = clamp(0.5f * clip.z / clip.w + 0.5f, 0.0f, 1.0f);
  }
  if (u_facing > 0 && !s.front) return false;
  if (u_facing < 0 && s.front) return false;
  return true;
}
