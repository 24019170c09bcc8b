// Exact ray intersections with the analytic shapes of a scene, in their object space: the GLSL
// port (float) of geometry/analytic_primitives.cpp, with the same normals (out of the solid;
// quads +Z) and texture coordinates. Shape codes SHAPE_* are the contract's.

#include "lib/contract.glsl"

const float SHAPE_PI = 3.14159265358979f;

struct ShapeHit {
  bool hit;
  float t;      // along the ray's (unnormalised) direction
  vec3 normal;  // unit, object space
  vec2 uv;
};

void shape_offer(inout ShapeHit h, float t_min, float t, vec3 normal, vec2 uv) {
  if (t > t_min && t < h.t) {
    h.hit = true;
    h.t = t;
    h.normal = normal;
    h.uv = uv;
  }
}

// Real roots of a t^2 + 2 b t + c = 0, ascending (numerically stable form).
bool shape_quadratic(float a, float b, float c, out float t0, out float t1) {
  t0 = 0.0f;
  t1 = 0.0f;
  float disc = b * b - a * c;
  if (disc < 0.0f || a == 0.0f) return false;
  float q = -(b + (b >= 0.0f ? 1.0f : -1.0f) * sqrt(disc));
  if (q == 0.0f) return true;
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) {
    float s = t0;
    t0 = t1;
    t1 = s;
  }
  return true;
}

float shape_azimuth_u(float x, float z) { return atan(x, z) / (2.0f * SHAPE_PI) + 0.5f; }

void shape_cylinder_side(inout ShapeHit h, float t_min, vec3 o, vec3 d, float r, float height,
                         bool inward) {
  float t0, t1;
  if (!shape_quadratic(d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - r * r,
                       t0, t1))
    return;
  for (int k = 0; k < 2; k++) {
    float t = k == 0 ? t0 : t1;
    vec3 p = o + t * d;
    if (abs(p.y) > 0.5f * height) continue;
    vec3 n = normalize(vec3(p.x, 0.0f, p.z));
    shape_offer(h, t_min, t, inward ? -n : n, vec2(shape_azimuth_u(p.x, p.z), p.y / height + 0.5f));
  }
}

void shape_cylinder_caps(inout ShapeHit h, float t_min, vec3 o, vec3 d, float r_outer,
                         float r_inner, float height) {
  if (d.y == 0.0f) return;
  for (int k = 0; k < 2; k++) {
    float side = k == 0 ? -1.0f : 1.0f;
    float t = (side * 0.5f * height - o.y) / d.y;
    vec3 p = o + t * d;
    float r2 = p.x * p.x + p.z * p.z;
    if (r2 > r_outer * r_outer || r2 < r_inner * r_inner) continue;
    shape_offer(h, t_min, t, vec3(0.0f, side, 0.0f),
                vec2(p.x / (2.0f * r_outer) + 0.5f, p.z / (2.0f * r_outer) + 0.5f));
  }
}

void shape_box_face(inout ShapeHit h, float t_min, vec3 o, vec3 d, vec3 half_size, float t,
                    int axis) {
  if (axis < 0) return;
  vec3 p = o + t * d;
  vec3 n = vec3(0.0f);
  n[axis] = p[axis] > 0.0f ? 1.0f : -1.0f;
  int a1 = axis == 0 ? 2 : 0;
  int a2 = axis == 1 ? 2 : 1;
  shape_offer(h, t_min, t, n,
              vec2(p[a1] / (2.0f * half_size[a1]) + 0.5f, p[a2] / (2.0f * half_size[a2]) + 0.5f));
}

void shape_box(inout ShapeHit h, float t_min, vec3 o, vec3 d, vec3 half_size) {
  float t_enter = -3.0e38f;
  float t_exit = 3.0e38f;
  int enter_axis = -1;
  int exit_axis = -1;
  for (int i = 0; i < 3; i++) {
    if (d[i] == 0.0f) {
      if (abs(o[i]) > half_size[i]) return;
      continue;
    }
    float ta = (-half_size[i] - o[i]) / d[i];
    float tb = (half_size[i] - o[i]) / d[i];
    if (ta > tb) {
      float s = ta;
      ta = tb;
      tb = s;
    }
    if (ta > t_enter) {
      t_enter = ta;
      enter_axis = i;
    }
    if (tb < t_exit) {
      t_exit = tb;
      exit_axis = i;
    }
  }
  if (t_enter > t_exit) return;
  shape_box_face(h, t_min, o, d, half_size, t_enter, enter_axis);
  shape_box_face(h, t_min, o, d, half_size, t_exit, exit_axis);
}

// The nearest hit with t in (t_min, t_max) of o + t d with shape `type` of parameters `shape`
// (radius, height, thickness) and `size` (box, quad and slab extents).
ShapeHit intersect_shape(int type, vec4 shape, vec3 size, vec3 o, vec3 d, float t_min,
                         float t_max) {
  ShapeHit h;
  h.hit = false;
  h.t = t_max;
  h.normal = vec3(0.0f);
  h.uv = vec2(0.0f);
  float radius = shape.x;
  float height = shape.y;
  float thickness = shape.z;
  if (type == SHAPE_SPHERE) {
    float t0, t1;
    if (shape_quadratic(dot(d, d), dot(o, d), dot(o, o) - radius * radius, t0, t1)) {
      for (int k = 0; k < 2; k++) {
        float t = k == 0 ? t0 : t1;
        vec3 p = o + t * d;
        float v = asin(clamp(p.y / radius, -1.0f, 1.0f)) / SHAPE_PI + 0.5f;
        shape_offer(h, t_min, t, normalize(p), vec2(shape_azimuth_u(p.x, p.z), v));
      }
    }
  } else if (type == SHAPE_QUAD) {
    if (d.z != 0.0f) {
      float t = -o.z / d.z;
      vec3 p = o + t * d;
      if (abs(p.x) <= 0.5f * size.x && abs(p.y) <= 0.5f * size.y)
        shape_offer(h, t_min, t, vec3(0.0f, 0.0f, 1.0f),
                    vec2(p.x / size.x + 0.5f, p.y / size.y + 0.5f));
    }
  } else if (type == SHAPE_BOX) {
    shape_box(h, t_min, o, d, 0.5f * size);
  } else if (type == SHAPE_SLAB) {
    shape_box(h, t_min, o, d, 0.5f * vec3(size.x, size.y, thickness));
  } else if (type == SHAPE_CYLINDER) {
    shape_cylinder_side(h, t_min, o, d, radius, height, false);
    shape_cylinder_caps(h, t_min, o, d, radius, 0.0f, height);
  } else if (type == SHAPE_HOLLOW_CYLINDER) {
    float inner = radius - thickness;
    shape_cylinder_side(h, t_min, o, d, radius, height, false);
    shape_cylinder_side(h, t_min, o, d, inner, height, true);
    shape_cylinder_caps(h, t_min, o, d, radius, inner, height);
  }
  return h;
}
