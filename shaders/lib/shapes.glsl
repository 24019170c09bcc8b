// Exact ray intersections with the analytic shapes of a scene (sphere, quad, box, cylinder, slab,
// hollow cylinder) in their object space: centred on the origin, cylinders along Y, quads and
// slabs facing +Z (gfield/scene.hpp). Normals point out of the solid (quads: +Z); texture
// coordinates as docs/scenes.md says. Shape codes SHAPE_* are the contract's.
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md) in `real`:
// included by the shaders (float) and by geometry/analytic_primitives.cpp (double: the reference
// tracer's ground truth), whose includer defines `real`, `rvec2`..`rvec4` and GF_PI in double.

#ifndef __cplusplus
#include "lib/contract.glsl"
#endif

struct ShapeHit {
  bool hit;
  real t;        // along the ray's (unnormalised) direction
  rvec3 normal;  // unit, object space
  rvec2 uv;
};

void shape_offer(GF_INOUT(ShapeHit) h, real t_min, real t, rvec3 normal, rvec2 uv) {
  if (t > t_min && t < h.t) {
    h.hit = true;
    h.t = t;
    h.normal = normal;
    h.uv = uv;
  }
}

// Real roots of a t^2 + 2 b t + c = 0, ascending (numerically stable form).
bool shape_quadratic(real a, real b, real c, GF_OUT(real) t0, GF_OUT(real) t1) {
  t0 = 0.0;
  t1 = 0.0;
  real disc = b * b - a * c;
  if (disc < 0.0 || a == 0.0) return false;
  real q = -(b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
  if (q == 0.0) return true;
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1) {
    real s = t0;
    t0 = t1;
    t1 = s;
  }
  return true;
}

real shape_azimuth_u(real x, real z) { return atan(x, z) / (2.0 * GF_PI) + 0.5; }

// The lateral surface of the infinite cylinder x^2 + z^2 = r^2 clipped to |y| <= height / 2.
void shape_cylinder_side(GF_INOUT(ShapeHit) h, real t_min, rvec3 o, rvec3 d, real r, real height,
                         bool inward) {
  real t0;
  real t1;
  if (!shape_quadratic(d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - r * r,
                       t0, t1))
    return;
  for (int k = 0; k < 2; k++) {
    real t = k == 0 ? t0 : t1;
    rvec3 p = o + t * d;
    if (abs(p.y) > 0.5 * height) continue;
    rvec3 n = normalize(rvec3(p.x, 0.0, p.z));
    shape_offer(h, t_min, t, inward ? -n : n, rvec2(shape_azimuth_u(p.x, p.z), p.y / height + 0.5));
  }
}

// The caps y = +-height / 2 where r_inner^2 <= x^2 + z^2 <= r_outer^2.
void shape_cylinder_caps(GF_INOUT(ShapeHit) h, real t_min, rvec3 o, rvec3 d, real r_outer,
                         real r_inner, real height) {
  if (d.y == 0.0) return;
  for (int k = 0; k < 2; k++) {
    real side = k == 0 ? -1.0 : 1.0;
    real t = (side * 0.5 * height - o.y) / d.y;
    rvec3 p = o + t * d;
    real r2 = p.x * p.x + p.z * p.z;
    if (r2 > r_outer * r_outer || r2 < r_inner * r_inner) continue;
    shape_offer(h, t_min, t, rvec3(0.0, side, 0.0),
                rvec2(p.x / (2.0 * r_outer) + 0.5, p.z / (2.0 * r_outer) + 0.5));
  }
}

// The face of a box crossed at t, perpendicular to `axis` (-1: none), on the side the point lies
// on. Texture coordinates: X faces (z, y), Y faces (x, z), Z faces (x, y).
void shape_box_face(GF_INOUT(ShapeHit) h, real t_min, rvec3 o, rvec3 d, rvec3 half_size, real t,
                    int axis) {
  if (axis < 0) return;
  rvec3 p = o + t * d;
  rvec3 n = rvec3(0.0);
  n[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
  int a1 = axis == 0 ? 2 : 0;
  int a2 = axis == 1 ? 2 : 1;
  shape_offer(h, t_min, t, n,
              rvec2(p[a1] / (2.0 * half_size[a1]) + 0.5, p[a2] / (2.0 * half_size[a2]) + 0.5));
}

void shape_box(GF_INOUT(ShapeHit) h, real t_min, rvec3 o, rvec3 d, rvec3 half_size) {
  real t_enter = -GF_FAR;
  real t_exit = GF_FAR;
  int enter_axis = -1;
  int exit_axis = -1;
  for (int i = 0; i < 3; i++) {
    if (d[i] == 0.0) {
      if (abs(o[i]) > half_size[i]) return;
      continue;
    }
    real ta = (-half_size[i] - o[i]) / d[i];
    real tb = (half_size[i] - o[i]) / d[i];
    if (ta > tb) {
      real s = ta;
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

// The nearest hit with t in (t_min, t_max) of o + t d with shape `type` (SHAPE_*; meshes are not
// analytic: no hit) of parameters `shape` (radius, height, thickness) and `size` (box, quad and
// slab extents).
ShapeHit intersect_shape(int type, rvec4 shape, rvec3 size, rvec3 o, rvec3 d, real t_min,
                         real t_max) {
  ShapeHit h;
  h.hit = false;
  h.t = t_max;
  h.normal = rvec3(0.0);
  h.uv = rvec2(0.0);
  real radius = shape.x;
  real height = shape.y;
  real thickness = shape.z;
  if (type == SHAPE_SPHERE) {
    real t0;
    real t1;
    if (shape_quadratic(dot(d, d), dot(o, d), dot(o, o) - radius * radius, t0, t1)) {
      for (int k = 0; k < 2; k++) {
        real t = k == 0 ? t0 : t1;
        rvec3 p = o + t * d;
        real v = asin(clamp(p.y / radius, -1.0, 1.0)) / GF_PI + 0.5;
        shape_offer(h, t_min, t, normalize(p), rvec2(shape_azimuth_u(p.x, p.z), v));
      }
    }
  } else if (type == SHAPE_QUAD) {
    if (d.z != 0.0) {
      real t = -o.z / d.z;
      rvec3 p = o + t * d;
      if (abs(p.x) <= 0.5 * size.x && abs(p.y) <= 0.5 * size.y)
        shape_offer(h, t_min, t, rvec3(0.0, 0.0, 1.0),
                    rvec2(p.x / size.x + 0.5, p.y / size.y + 0.5));
    }
  } else if (type == SHAPE_BOX) {
    shape_box(h, t_min, o, d, 0.5 * size);
  } else if (type == SHAPE_SLAB) {
    shape_box(h, t_min, o, d, 0.5 * rvec3(size.x, size.y, thickness));
  } else if (type == SHAPE_CYLINDER) {
    shape_cylinder_side(h, t_min, o, d, radius, height, false);
    shape_cylinder_caps(h, t_min, o, d, radius, 0.0, height);
  } else if (type == SHAPE_HOLLOW_CYLINDER) {
    real inner = radius - thickness;
    shape_cylinder_side(h, t_min, o, d, radius, height, false);
    shape_cylinder_side(h, t_min, o, d, inner, height, true);
    shape_cylinder_caps(h, t_min, o, d, radius, inner, height);
  }
  return h;
}
