// Analytic ray-shape intersections (double precision, numerically stable quadratics).

#include "preprocess/analytic_primitives.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gfield {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Keeps the nearest candidate in (t_min, best.t).
struct Nearest {
  double t_min;
  PrimitiveHit best;
  bool found = false;

  void offer(double t, glm::dvec3 normal, glm::dvec2 uv) {
    if (t > t_min && t < best.t) {
      best = {t, normal, uv};
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
void cylinder_side(Nearest& n, glm::dvec3 o, glm::dvec3 d, double r, double h, bool inward) {
  double t0, t1;
  const double a = d.x * d.x + d.z * d.z;
  if (!solve_quadratic(a, o.x * d.x + o.z * d.z, o.x * o.x + o.z * o.z - r * r, t0, t1))
    return;
  for (const double t : {t0, t1}) {
    const glm::dvec3 p = o + t * d;
    if (std::abs(p.y) > 0.5 * h)
      continue;
    glm::dvec3 normal(p.x / r, 0.0, p.z / r);
    if (inward)
      normal = -normal;
    n.offer(t, glm::normalize(normal), {azimuth_u(p.x, p.z), p.y / h + 0.5});
  }
}

/// The caps y = +-h/2 where r_inner^2 <= x^2 + z^2 <= r_outer^2.
void cylinder_caps(Nearest& n, glm::dvec3 o, glm::dvec3 d, double r_outer, double r_inner,
                   double h) {
  if (d.y == 0.0)
    return;
  for (const double side : {-1.0, 1.0}) {
    const double t = (side * 0.5 * h - o.y) / d.y;
    const glm::dvec3 p = o + t * d;
    const double r2 = p.x * p.x + p.z * p.z;
    if (r2 > r_outer * r_outer || r2 < r_inner * r_inner)
      continue;
    n.offer(t, {0.0, side, 0.0}, {p.x / (2.0 * r_outer) + 0.5, p.z / (2.0 * r_outer) + 0.5});
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
  auto face = [&](double t, int axis) {
    if (axis < 0)
      return;
    const glm::dvec3 p = o + t * d;
    glm::dvec3 normal(0.0);
    // The face is on the side the point lies on (the ray crosses it entering or leaving).
    normal[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
    const int a1 = axis == 0 ? 2 : 0;  // X faces: (z, y); Y faces: (x, z); Z faces: (x, y)
    const int a2 = axis == 1 ? 2 : 1;
    n.offer(t, normal, {p[a1] / (2.0 * half[a1]) + 0.5, p[a2] / (2.0 * half[a2]) + 0.5});
  };
  face(t_enter, enter_axis);
  face(t_exit, exit_axis);
}

}  // namespace

bool intersect_shape(const Shape& shape, glm::dvec3 o, glm::dvec3 d, double t_min, double t_max,
                     PrimitiveHit& hit) {
  Nearest n{t_min, {t_max, glm::dvec3(0.0), glm::dvec2(0.0)}};
  switch (shape.type) {
    case ShapeType::kMesh:
      return false;
    case ShapeType::kSphere: {
      const double r = shape.radius;
      double t0, t1;
      if (!solve_quadratic(glm::dot(d, d), glm::dot(o, d), glm::dot(o, o) - r * r, t0, t1))
        break;
      for (const double t : {t0, t1}) {
        const glm::dvec3 p = o + t * d;
        const double v = std::asin(std::clamp(p.y / r, -1.0, 1.0)) / kPi + 0.5;
        n.offer(t, glm::normalize(p), {azimuth_u(p.x, p.z), v});
      }
      break;
    }
    case ShapeType::kQuad: {
      if (d.z == 0.0)
        break;
      const double t = -o.z / d.z;
      const glm::dvec3 p = o + t * d;
      const double hx = 0.5 * shape.size.x, hy = 0.5 * shape.size.y;
      if (std::abs(p.x) <= hx && std::abs(p.y) <= hy) {
        n.offer(t, {0.0, 0.0, 1.0}, {p.x / shape.size.x + 0.5, p.y / shape.size.y + 0.5});
      }
      break;
    }
    case ShapeType::kBox:
      box(n, o, d, 0.5 * glm::dvec3(shape.size));
      break;
    case ShapeType::kSlab:
      box(n, o, d, 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness));
      break;
    case ShapeType::kCylinder:
      cylinder_side(n, o, d, shape.radius, shape.height, false);
      cylinder_caps(n, o, d, shape.radius, 0.0, shape.height);
      break;
    case ShapeType::kHollowCylinder: {
      const double inner = double(shape.radius) - double(shape.thickness);
      cylinder_side(n, o, d, shape.radius, shape.height, false);
      cylinder_side(n, o, d, inner, shape.height, true);
      cylinder_caps(n, o, d, shape.radius, inner, shape.height);
      break;
    }
  }
  if (n.found)
    hit = n.best;
  return n.found;
}

void shape_bounds(const Shape& shape, glm::dvec3& lo, glm::dvec3& hi) {
  glm::dvec3 half(0.0);
  switch (shape.type) {
    case ShapeType::kMesh:
      break;
    case ShapeType::kSphere:
      half = glm::dvec3(shape.radius);
      break;
    case ShapeType::kQuad:
      half = glm::dvec3(0.5 * shape.size.x, 0.5 * shape.size.y, 0.0);
      break;
    case ShapeType::kBox:
      half = 0.5 * glm::dvec3(shape.size);
      break;
    case ShapeType::kSlab:
      half = 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness);
      break;
    case ShapeType::kCylinder:
    case ShapeType::kHollowCylinder:
      half = glm::dvec3(shape.radius, 0.5 * shape.height, shape.radius);
      break;
  }
  lo = -half;
  hi = half;
}

}  // namespace gfield
