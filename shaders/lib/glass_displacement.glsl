// Objects seen through glass by vertex displacement (Mukai, Makino & Chang 2013): where a vertex
// behind a parallel glass plate or a hollow glass cylinder is SEEN from the eye, so that drawing
// the displaced vertex without any glass gives the refracted picture.
//
// ONE source for the CPU and the GPU, in the CPU/GPU dialect (docs/architecture.md; float),
// included by core/src/glass_displacement.cpp and by shaders/glass_scene.vert.
//
// Indices are relative: n_rel = n_glass / n_outside (> 0); the outside (air) and the hollow
// cylinder's interior have index 1 relative to it.

#ifndef __cplusplus
#include "lib/contract.glsl"
#endif

// Newton iterations of the plate's equation 5 (each keeps the root bracketed), of the cylinder's
// path search, and the cylinder's convergence tolerance (distance from the vertex to the traced
// ray, relative to the eye-vertex distance).
GF_CONST int GD_PLATE_ITERATIONS = 24;
GF_CONST int GD_CYLINDER_ITERATIONS = 16;
GF_CONST float GD_CYLINDER_TOLERANCE = 1.0e-6f;

// ---------------------------------------------------------------------------------------------
// Parallel plate (section 2.1 and 2.2).

// The paper's equation 5 in the plate's frame, in terms of s = sin(theta):
//   f(s) = (y - W) tan(theta) + W tan(phi) - x,  sin(phi) = s / n_rel   (Snell, equation 4),
// with x >= 0 the distance of the vertex from the normal through the eye and y > W its distance
// along the normal. f is increasing and convex on [0, 1), so the root is bracketed by
//   s_lo: the direct line to the vertex (tan(theta) = x / y): f <= 0,
//   s_hi: the plate removed (tan(theta) = x / (y - W)):      f >= 0,
// and Newton's method started at s_hi stays inside [s_lo, s_hi] and converges monotonically; a
// step that would leave the bracket is replaced by bisection all the same.
float gd_plate_f(float s, float x, float y, float w, float n_rel) {
  float tan_theta = s / sqrt(max(1.0f - s * s, 1.0e-30f));
  float tan_phi = s / sqrt(max(n_rel * n_rel - s * s, 1.0e-30f));
  return (y - w) * tan_theta + w * tan_phi - x;
}

float gd_plate_df(float s, float y, float w, float n_rel) {
  float c2 = max(1.0f - s * s, 1.0e-30f);
  float g2 = max(n_rel * n_rel - s * s, 1.0e-30f);
  return (y - w) / (c2 * sqrt(c2)) + w * n_rel * n_rel / (g2 * sqrt(g2));
}

// sin(theta), the incidence angle of equation 5 (root in [s_lo, s_hi]); requires y > w > 0,
// x >= 0, n_rel >= 1.
float gd_plate_incidence_sine(float x, float y, float w, float n_rel) {
  float lo = x / sqrt(x * x + y * y);
  float hi = x / sqrt(x * x + (y - w) * (y - w));
  float s = hi;
  for (int k = 0; k < GD_PLATE_ITERATIONS; k++) {
    float f = gd_plate_f(s, x, y, w, n_rel);
    if (f > 0.0f) {
      hi = s;
    } else {
      lo = s;
    }
    float next = s - f / gd_plate_df(s, y, w, n_rel);
    if (!(next > lo && next < hi)) next = 0.5f * (lo + hi);
    if (abs(next - s) <= 1.0e-7f * max(s, 1.0e-6f)) {
      s = next;
      break;
    }
    s = next;
  }
  return s;
}

// The movement L of equation 2 for incidence sine s: L = W (1 - tan(phi) / tan(theta)), written
// as W (1 - cos(theta) / (n_rel cos(phi))) so that it holds at theta = 0 too.
float gd_plate_shift(float s, float w, float n_rel) {
  float cos_theta = sqrt(max(1.0f - s * s, 0.0f));
  float cos_phi = sqrt(max(1.0f - s * s / (n_rel * n_rel), 0.0f));
  return w * (1.0f - cos_theta / (n_rel * cos_phi));
}

// Where vertex `a` (world) is seen from `eye` through a parallel plate: centre `centre`, unit
// normal `normal` (either sign), thickness `w`, relative index `n_rel` >= 1. The system is
// rotated into the plate's frame (section 2.2, any orientation): Y along the normal away from the
// eye, X towards the vertex in the plane of incidence; there A(x, y) moves to B(x, y - L) and
// the inverse rotation gives the world position. Vertices in front of the plate (and an eye
// inside the plate) are returned unchanged.
vec3 gd_plate_displace(vec3 eye, vec3 a, vec3 centre, vec3 normal, float w, float n_rel) {
  vec3 ny = dot(centre - eye, normal) >= 0.0f ? normal : -normal;
  float front = dot(centre - eye, ny) - 0.5f * w;  // eye to the near face, along ny
  vec3 rel = a - eye;
  float y = dot(rel, ny);
  if (!(front > 0.0f) || !(y > front)) return a;
  // A vertex inside the glass is seen through the near face alone: equations 5 and 2 with the
  // glass ending at the vertex (W = y - front), which is the one-interface case of equations 6-8
  // and meets the plate's answer at the far face.
  float glass = min(w, y - front);
  vec3 lateral = rel - y * ny;
  float x = sqrt(dot(lateral, lateral));
  vec3 nx = x > 0.0f ? lateral / x : vec3(0.0f);
  vec3 nz = cross(nx, ny);
  // Rotation into the plate's frame: rows nx, ny, nz.
  mat3 to_plate = transpose(mat3(nx, ny, nz));
  vec3 local = to_plate * rel;  // = (x, y, 0)
  float s = gd_plate_incidence_sine(local.x, local.y, glass, n_rel);
  local.y = local.y - gd_plate_shift(s, glass, n_rel);
  return eye + transpose(to_plate) * local;
}

// ---------------------------------------------------------------------------------------------
// Hollow cylinder (section 2.3), in the cylinder's object space: axis Y through the origin, outer
// radius R, inner radius r = R - W, walls of index n_rel, air outside and inside. The walls are
// taken as infinite along Y. A path through the glass is a fixed sequence of interfaces:
// outer in, inner in, inner out, outer out: 4 refractions (A B C D).
GF_CONST int GD_PATH_BOTH_WALLS = 0;
// Outer in, (total internal reflection at the inner surface,) outer out: through the wall only,
// 2 refractions.
GF_CONST int GD_PATH_VERGE = 1;
// Outer in, inner in: into the interior, 2 refractions.
GF_CONST int GD_PATH_FRONT_WALL = 2;
// Inner out, outer out: from the open top out through one wall.
GF_CONST int GD_PATH_BACK_WALL = 3;
//
// A ray entering the outer surface at distance b < R from the axis meets the inner surface
// unless b > n r; there it is totally reflected when b > r. So through the wall's silhouette band
// (r < b < R) light comes by two refractions and one total internal reflection: the verge path.

struct GdPath {
  bool valid;
  int count;        // interface points (2 to 4)
  vec3 point[4];    // interface points, in path order (the paper's A, B, C, D)
  vec3 facing[4];   // unit normals there, facing the side the ray comes from
  vec3 dir[5];      // unit directions: dir[0] from the eye, dir[k] after interface point k
  float index[5];   // relative index of the medium of dir[k]
};

// The glass a path crosses: the hollow cylinder and one of its GD_PATH_* paths.
struct GdGlass {
  int path;  // GD_PATH_*
  float outer_radius;
  float inner_radius;
  float n_rel;
};

GdGlass gd_cylinder_glass(int path, float outer_radius, float inner_radius, float n_rel) {
  GdGlass g;
  g.path = path;
  g.outer_radius = outer_radius;
  g.inner_radius = inner_radius;
  g.n_rel = n_rel;
  return g;
}

int gd_path_steps(int path) {
  if (path == GD_PATH_BOTH_WALLS) return 4;
  if (path == GD_PATH_VERGE) return 3;
  return 2;
}

// Step k of `path` meets the outer surface (else the inner one).
bool gd_step_outer(int path, int k) {
  if (path == GD_PATH_BOTH_WALLS) return k == 0 || k == 3;
  if (path == GD_PATH_VERGE) return k != 1;
  if (path == GD_PATH_FRONT_WALL) return k == 0;
  return k == 1;
}

// Step k of `path` is the far crossing of its cylinder (the ray leaves the cylinder there).
bool gd_step_far(int path, int k) {
  if (path == GD_PATH_BOTH_WALLS) return k >= 2;
  if (path == GD_PATH_VERGE) return k == 2;
  if (path == GD_PATH_FRONT_WALL) return false;
  return true;
}

// Step k of `path` is the verge's reflection: taken only when the surface is met, and then it
// must be a total internal reflection.
bool gd_step_reflects(int path, int k) { return path == GD_PATH_VERGE && k == 1; }

// No path yet: invalid, no interface met, the ray along `d` in the outside's index.
GdPath gd_empty_path(vec3 d) {
  GdPath p;
  p.valid = false;
  p.count = 0;
  for (int k = 0; k < 4; k++) {
    p.point[k] = vec3(0.0f);
    p.facing[k] = vec3(0.0f);
  }
  for (int k = 0; k < 5; k++) {
    p.dir[k] = d;
    p.index[k] = 1.0f;
  }
  return p;
}

// The ray from `origin` along unit `d` followed through the steps of `path`, refracting by vector
// Snell (or reflecting) at each; invalid when a surface is missed (or behind), light is totally
// reflected where it should pass, or passes where the verge needs a total internal reflection.
GdPath gd_cylinder_trace(int path, float outer_radius, float inner_radius, float n_rel,
                         vec3 origin, vec3 d) {
  GdPath p = gd_empty_path(d);
  vec3 o = origin;
  vec3 dir = d;
  float index = 1.0f;
  int steps = gd_path_steps(path);
  for (int k = 0; k < steps; k++) {
    bool reflects = gd_step_reflects(path, k);
    float radius = gd_step_outer(path, k) ? outer_radius : inner_radius;
    float qa = dir.x * dir.x + dir.z * dir.z;
    float qb = o.x * dir.x + o.z * dir.z;
    float qc = o.x * o.x + o.z * o.z - radius * radius;
    float disc = qb * qb - qa * qc;
    bool met = qa > 0.0f && disc >= 0.0f;
    float t = 0.0f;
    if (met) {
      float q = -(qb + (qb >= 0.0f ? 1.0f : -1.0f) * sqrt(disc));
      float t0 = q / qa;
      float t1 = q != 0.0f ? qc / q : t0;
      t = gd_step_far(path, k) ? max(t0, t1) : min(t0, t1);
      met = t > 0.0f;
    }
    if (!met) {
      if (reflects) continue;
      return p;
    }
    o = o + t * dir;
    vec3 outward = normalize(vec3(o.x, 0.0f, o.z));
    vec3 m = dot(dir, outward) < 0.0f ? outward : -outward;
    float next_index = index == 1.0f ? n_rel : 1.0f;
    vec3 refracted = refract(dir, m, index / next_index);
    bool total = dot(refracted, refracted) == 0.0f;
    if (total != reflects) return p;
    if (reflects) {
      dir = reflect(dir, m);
      next_index = index;
    } else {
      dir = normalize(refracted);
    }
    index = next_index;
    p.point[p.count] = o;
    p.facing[p.count] = m;
    p.dir[p.count + 1] = dir;
    p.index[p.count + 1] = index;
    p.count = p.count + 1;
  }
  p.valid = true;
  return p;
}

GdPath gd_trace(GdGlass g, vec3 origin, vec3 d) {
  return gd_cylinder_trace(g.path, g.outer_radius, g.inner_radius, g.n_rel, origin, d);
}

// The miss of the traced path at vertex q: q's offset from the final ray, in the basis (e1, e2).
// The z component is the distance from the last interface to q along the final ray.
vec3 gd_path_miss(GdPath p, vec3 q, vec3 e1, vec3 e2) {
  vec3 last_dir = p.dir[p.count];
  vec3 rel = q - p.point[p.count - 1];
  float along = dot(rel, last_dir);
  vec3 off = rel - along * last_dir;
  return vec3(dot(off, e1), dot(off, e2), along);
}

vec3 gd_direction(vec3 d0, vec3 e1, vec3 e2, float u, float v) {
  return normalize(d0 + u * e1 + v * e2);
}

// The path through glass g from `eye` that reaches vertex q (the cylinder's object space):
// the eye ray's direction is found by Newton's method on the 2 angles of the miss (Jacobian by
// finite differences, steps halved while they leave the valid paths or do not reduce the miss),
// started from the straight line to q (or, when that one does not take the path, from the best
// of a fan of lines across the cylinder). Invalid when it does not converge or q is not beyond
// the last interface.
GdPath gd_solve(GdGlass g, vec3 eye, vec3 q) {
  vec3 d0 = normalize(q - eye);
  vec3 helper = abs(d0.y) < 0.9f ? vec3(0.0f, 1.0f, 0.0f) : vec3(1.0f, 0.0f, 0.0f);
  vec3 e1 = normalize(cross(d0, helper));
  vec3 e2 = cross(d0, e1);
  float scale = length(q - eye) + length(q) + length(eye);
  float u = 0.0f;
  float v = 0.0f;
  GdPath p = gd_trace(g, eye, d0);
  if (!p.valid) {
    // Start instead from the valid one of a fan of lines across the axis (e1 is horizontal
    // unless the line is nearly vertical) that misses q least; the fan's step is half the wall's
    // apparent width, so no band of valid lines falls between two of them.
    float best = GF_FAR;
    float distance_to_axis = max(sqrt(eye.x * eye.x + eye.z * eye.z), g.outer_radius);
    float span = 2.0f * g.outer_radius / distance_to_axis;
    float fan_step =
        max(0.5f * (g.outer_radius - g.inner_radius) / distance_to_axis, span / 32.0f);
    for (int k = 0; k <= 64; k++) {
      float offset = -span + fan_step * float(k);
      if (offset > span) break;
      GdPath trial = gd_trace(g, eye, gd_direction(d0, e1, e2, offset, 0.0f));
      if (!trial.valid) continue;
      vec3 trial_miss = gd_path_miss(trial, q, e1, e2);
      float err = trial_miss.x * trial_miss.x + trial_miss.y * trial_miss.y;
      if (err < best) {
        best = err;
        u = offset;
        p = trial;
      }
    }
    if (!p.valid) return p;
  }
  vec3 miss = gd_path_miss(p, q, e1, e2);
  float h = 1.0e-3f;
  bool converged = false;
  for (int it = 0; it < GD_CYLINDER_ITERATIONS; it++) {
    float err = sqrt(miss.x * miss.x + miss.y * miss.y);
    if (err <= GD_CYLINDER_TOLERANCE * scale) {
      converged = true;
      break;
    }
    // Finite differences away from the current point (one-sided, towards the valid side).
    GdPath pu = gd_trace(g, eye,
                                  gd_direction(d0, e1, e2, u + h, v));
    float hu = h;
    if (!pu.valid) {
      hu = -h;
      pu = gd_trace(g, eye,
                             gd_direction(d0, e1, e2, u - h, v));
    }
    GdPath pv = gd_trace(g, eye,
                                  gd_direction(d0, e1, e2, u, v + h));
    float hv = h;
    if (!pv.valid) {
      hv = -h;
      pv = gd_trace(g, eye,
                             gd_direction(d0, e1, e2, u, v - h));
    }
    if (!pu.valid) return pu;
    if (!pv.valid) return pv;
    vec3 mu = gd_path_miss(pu, q, e1, e2);
    vec3 mv = gd_path_miss(pv, q, e1, e2);
    float j11 = (mu.x - miss.x) / hu;
    float j21 = (mu.y - miss.y) / hu;
    float j12 = (mv.x - miss.x) / hv;
    float j22 = (mv.y - miss.y) / hv;
    float det = j11 * j22 - j12 * j21;
    if (det == 0.0f) break;
    float du = -(j22 * miss.x - j12 * miss.y) / det;
    float dv = -(-j21 * miss.x + j11 * miss.y) / det;
    // Backtracking: halve the step until the path stays valid and the miss shrinks.
    bool accepted = false;
    float lambda = 1.0f;
    for (int b = 0; b < 12 && !accepted; b++) {
      GdPath trial = gd_trace(g, eye,
                                       gd_direction(d0, e1, e2, u + lambda * du, v + lambda * dv));
      if (trial.valid) {
        vec3 trial_miss = gd_path_miss(trial, q, e1, e2);
        if (trial_miss.x * trial_miss.x + trial_miss.y * trial_miss.y < err * err) {
          u = u + lambda * du;
          v = v + lambda * dv;
          p = trial;
          miss = trial_miss;
          accepted = true;
        }
      }
      lambda = 0.5f * lambda;
    }
    if (!accepted) break;
    // The finite-difference step follows the Newton step's size.
    h = clamp(0.5f * sqrt(du * du + dv * dv), 1.0e-5f, 1.0e-3f);
  }
  if (!converged) {
    float err = sqrt(miss.x * miss.x + miss.y * miss.y);
    converged = err <= GD_CYLINDER_TOLERANCE * scale;
  }
  p.valid = converged && miss.z > 0.0f;
  return p;
}

// The paper's inverse sequence Q -> Q_D -> Q_C -> Q_B -> Q' (= Q_A): at every interface, taken
// from its last to its first, the point moves along that interface's normal from depth L (behind
// the tangent plane) to depth L' = L n_A cos(theta) / (n_B cos(phi)) (equations 6-8, the eye at
// the previous interface point, theta the angle of incidence there, phi of refraction), which
// puts it on the straight continuation of the segment before the interface. At the verge's
// reflection cos(phi) = -cos(theta) and n_B = n_A: L' = -L, the mirror image. The result lies on
// the eye ray through the first interface point.
vec3 gd_path_virtual_point(GdPath p, vec3 q) {
  vec3 cur = q;
  for (int k = 3; k >= 0; k--) {
    if (k >= p.count) continue;
    vec3 m = p.facing[k];
    float cos_theta = -dot(p.dir[k], m);
    float cos_phi = -dot(p.dir[k + 1], m);
    float depth = dot(p.point[k] - cur, m);  // L
    float apparent = depth * p.index[k] * cos_theta / (p.index[k + 1] * cos_phi);  // L'
    cur = cur + (depth - apparent) * m;
  }
  return cur;
}

// Where vertex q is seen from `eye` through glass g; `ok` false (and q returned) when no path
// through g reaches q.
vec3 gd_displace(GdGlass g, vec3 eye, vec3 q, GF_OUT(bool) ok) {
  GdPath p = gd_solve(g, eye, q);
  ok = p.valid;
  if (!p.valid) return q;
  return gd_path_virtual_point(p, q);
}

// Where vertex q (object space of the cylinder) is seen from `eye` along `path`.
vec3 gd_cylinder_displace(int path, float outer_radius, float inner_radius, float n_rel, vec3 eye,
                          vec3 q, GF_OUT(bool) ok) {
  return gd_displace(gd_cylinder_glass(path, outer_radius, inner_radius, n_rel), eye, q, ok);
}
