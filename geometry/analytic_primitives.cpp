// Analytic ray-shape intersections (double precision, numerically stable quadratics).

#include "geometry/analytic_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gfield {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Which surface of a shape a candidate lies on; the normal and texture coordinates are computed
/// once, for the nearest candidate only.
enum Surface { kRound, kPlaneZ, kBoxFace, kOuterSide, kInnerSide, kCap };

/// Keeps the nearest candidate in (t_min, t).
struct Nearest {
  double t_min;
  double t;
  Surface surface = kRound;
  int axis = 0;  ///< kBoxFace: 0, 1, 2
  bool found = false;

  void offer(double candidate, Surface where, int face_axis = 0) {
    if (candidate > t_min && candidate < t) {
      t = candidate;
      surface = where;
      axis = face_axis;
      found = true;
    }
  }
};

/// Real roots of a t^2 + 2 b t + c = 0 (a > 0), ascending; false when none.
bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  const double disc = b * b - a * c;
  if (disc < 0.0 || a == 0.0)
    return false;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {
    t0 = t1 = 0.0;
    return true;
  }
  t0 = q / a;
  t1 = c / q;
  if (t0 > t1)
    std::swap(t0, t1);
  return true;
}

double azimuth_u(double x, double z) {
  return std::atan2(x, z) / (2.0 * kPi) + 0.5;
}

/// The lateral surface of the infinite cylinder x^2 + z^2 = r^2 clipped to |y| <= h/2.
void cylinder_side(Nearest& n, glm::dvec3 o, glm::dvec3 d, double r, double h, Surface where) {
  double t0, t1;
  const double a = d.x * d.x + d.z * d.z;
  if (!solve_quadratic(a, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - r * r, t0, t1))
    return;
  for (const double t : {t0, t1}) {
    if (std::abs(o.y + t * d.y) <= 0.5 * h)
      n.offer(t, where);
  }
}

/// The caps y = +-h/2 where r_inner^2 <= x^2 + z^2 <= r_outer^2.
void cylinder_caps(Nearest& n, glm::dvec3 o, glm::dvec3 d, double r_outer, double r_inner,
                   double h) {
  if (d.y == 0.0)
    return;
  for (const double side : {-1.0, 1.0}) {
    const double t = (side * 0.5 * h - o.y) / d.y;
    const double x = o.x + t * d.x, z = o.z + t * d.z;
    const double r2 = x * x + z * z;
    if (r2 <= r_outer * r_outer && r2 >= r_inner * r_inner)
      n.offer(t, kCap);
  }
}

void box(Nearest& n, glm::dvec3 o, glm::dvec3 d, glm::dvec3 half) {
  double t_enter = -std::numeric_limits<double>::infinity();
  double t_exit = std::numeric_limits<double>::infinity();
  int enter_axis = -1, exit_axis = -1;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (std::abs(o[i]) > half[i])
        return;
      continue;
    }
    double ta = (-half[i] - o[i]) / d[i];
    double tb = (half[i] - o[i]) / d[i];
    if (ta > tb)
      std::swap(ta, tb);
    if (ta > t_enter) {
      t_enter = ta;
      enter_axis = i;
    }
    if (tb < t_exit) {
      t_exit = tb;
      exit_axis = i;
    }
  }
  if (t_enter > t_exit)
    return;
  if (enter_axis >= 0)
    n.offer(t_enter, kBoxFace, enter_axis);
  if (exit_axis >= 0)
    n.offer(t_exit, kBoxFace, exit_axis);
}

/// Normal and texture coordinates of the nearest candidate at object-space point p.
void finish(const Shape& shape, const Nearest& n, glm::dvec3 p, glm::dvec3 half,
            PrimitiveHit& hit) {
  hit.t = n.t;
  switch (n.surface) {
    case kRound: {  // sphere
      const double r = shape.radius;
      hit.normal = glm::normalize(p);
      hit.uv = {azimuth_u(p.x, p.z), std::asin(std::clamp(p.y / r, -1.0, 1.0)) / kPi + 0.5};
      break;
    }
    case kPlaneZ:  // quad
      hit.normal = {0.0, 0.0, 1.0};
      hit.uv = {p.x / shape.size.x + 0.5, p.y / shape.size.y + 0.5};
      break;
    case kBoxFace: {
      // The face is on the side the point lies on (the ray crosses it entering or leaving).
      hit.normal = glm::dvec3(0.0);
      hit.normal[n.axis] = p[n.axis] > 0.0 ? 1.0 : -1.0;
      const int a1 = n.axis == 0 ? 2 : 0;  // X faces: (z, y); Y faces: (x, z); Z faces: (x, y)
      const int a2 = n.axis == 1 ? 2 : 1;
      hit.uv = {p[a1] / (2.0 * half[a1]) + 0.5, p[a2] / (2.0 * half[a2]) + 0.5};
      break;
    }
    case kOuterSide:
    case kInnerSide: {
      const glm::dvec3 radial = glm::normalize(glm::dvec3(p.x, 0.0, p.z));
      hit.normal = n.surface == kOuterSide ? radial : -radial;
      hit.uv = {azimuth_u(p.x, p.z), p.y / shape.height + 0.5};
      break;
    }
    case kCap:
      hit.normal = {0.0, p.y > 0.0 ? 1.0 : -1.0, 0.0};
      hit.uv = {p.x / (2.0 * shape.radius) + 0.5, p.z / (2.0 * shape.radius) + 0.5};
      break;
  }
}

}  // namespace

bool intersect_shape(const Shape& shape, glm::dvec3 o, glm::dvec3 d, double t_min, double t_max,
                     PrimitiveHit& hit) {
  Nearest n{t_min, t_max};
  glm::dvec3 half(0.0);
  switch (shape.type) {
    case ShapeType::kMesh:
      return false;
    case ShapeType::kSphere: {
      const double r = shape.radius;
      double t0, t1;
      if (solve_quadratic(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - r * r, t0, t1)) {
        n.offer(t0, kRound);
        n.offer(t1, kRound);
      }
      break;
    }
    case ShapeType::kQuad: {
      if (d.z == 0.0)
        break;
      const double t = -o.z / d.z;
      if (std::abs(o.x + t * d.x) <= 0.5 * shape.size.x &&
          std::abs(o.y + t * d.y) <= 0.5 * shape.size.y) {
        n.offer(t, kPlaneZ);
      }
      break;
    }
    case ShapeType::kBox:
      half = 0.5 * glm::dvec3(shape.size);
      box(n, o, d, half);
      break;
    case ShapeType::kSlab:
      half = 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness);
      box(n, o, d, half);
      break;
    case ShapeType::kCylinder:
      cylinder_side(n, o, d, shape.radius, shape.height, kOuterSide);
      cylinder_caps(n, o, d, shape.radius, 0.0, shape.height);
      break;
    case ShapeType::kHollowCylinder: {
      const double inner = double(shape.radius) - double(shape.thickness);
      cylinder_side(n, o, d, shape.radius, shape.height, kOuterSide);
      cylinder_side(n, o, d, inner, shape.height, kInnerSide);
      cylinder_caps(n, o, d, shape.radius, inner, shape.height);
      break;
    }
  }
  if (!n.found)
    return false;
  finish(shape, n, o + n.t * d, half, hit);
  return true;
}

}  // namespace gfield
