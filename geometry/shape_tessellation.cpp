#include "geometry/shape_tessellation.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace gfield {
namespace {

/// Appends a vertex; its index.
int vertex(TessellatedShape& s, glm::dvec3 p) {
  s.mesh.positions.push_back(p);
  return int(s.mesh.positions.size()) - 1;
}

/// Appends triangle (a, b, c) with corner uvs (ua, ub, uc).
void triangle(TessellatedShape& s, int a, int b, int c, glm::dvec2 ua, glm::dvec2 ub,
              glm::dvec2 uc) {
  s.mesh.triangles.emplace_back(a, b, c);
  s.corner_uv.insert(s.corner_uv.end(), {glm::vec2(ua), glm::vec2(ub), glm::vec2(uc)});
}

/// The point at azimuth index j of `n` (u = j / n: azimuth 2 pi (u - 0.5) from +Z towards +X, as
/// u = atan2(x, z) / 2 pi + 0.5), radius `r`, height `y`.
glm::dvec3 ring_point(int j, int n, double r, double y) {
  const double phi = 2.0 * glm::pi<double>() * (double(j) / n - 0.5);
  return {r * std::sin(phi), y, r * std::cos(phi)};
}

void sphere(TessellatedShape& s, double r, int n) {
  const int rings = n / 2;
  // Rings 1 .. rings-1 of n shared vertices each, from the bottom pole (v = 0) up.
  const auto index = [&](int i, int j) { return 2 + (i - 1) * n + j % n; };
  const auto uv = [&](int i, double j) { return glm::dvec2(j / n, double(i) / rings); };
  vertex(s, {0.0, -r, 0.0});
  vertex(s, {0.0, r, 0.0});
  for (int i = 1; i < rings; ++i) {
    const double latitude = glm::pi<double>() * (double(i) / rings - 0.5);
    for (int j = 0; j < n; ++j)
      vertex(s, ring_point(j, n, r * std::cos(latitude), r * std::sin(latitude)));
  }
  for (int j = 0; j < n; ++j) {
    triangle(s, 0, index(1, j + 1), index(1, j), uv(0, j + 0.5), uv(1, j + 1), uv(1, j));
    triangle(s, 1, index(rings - 1, j), index(rings - 1, j + 1), uv(rings, j + 0.5),
             uv(rings - 1, j), uv(rings - 1, j + 1));
    for (int i = 1; i + 1 < rings; ++i) {
      triangle(s, index(i, j), index(i, j + 1), index(i + 1, j + 1), uv(i, j), uv(i, j + 1),
               uv(i + 1, j + 1));
      triangle(s, index(i, j), index(i + 1, j + 1), index(i + 1, j), uv(i, j), uv(i + 1, j + 1),
               uv(i + 1, j));
    }
  }
}

/// A wall of radius r from y = -h/2 to h/2, its own shared vertices; facing out (`outward`) or
/// towards the axis; v = y / h + 0.5.
void wall(TessellatedShape& s, double r, double h, int n, bool outward) {
  const int first = int(s.mesh.positions.size());
  for (int j = 0; j < n; ++j) {
    vertex(s, ring_point(j, n, r, -0.5 * h));
    vertex(s, ring_point(j, n, r, 0.5 * h));
  }
  for (int j = 0; j < n; ++j) {
    const int b0 = first + 2 * j, t0 = b0 + 1, b1 = first + 2 * ((j + 1) % n), t1 = b1 + 1;
    const glm::dvec2 ub0(double(j) / n, 0.0), ut0(double(j) / n, 1.0);
    const glm::dvec2 ub1(double(j + 1) / n, 0.0), ut1(double(j + 1) / n, 1.0);
    if (outward) {
      triangle(s, b0, b1, t1, ub0, ub1, ut1);
      triangle(s, b0, t1, t0, ub0, ut1, ut0);
    } else {
      triangle(s, b0, t1, b1, ub0, ut1, ub1);
      triangle(s, b0, t0, t1, ub0, ut0, ut1);
    }
  }
}

/// A cap at height y facing +Y (`up`) or -Y: a disc (inner 0) or a ring between radii `inner`
/// and `outer`, its own vertices; u = x / (2 uv_radius) + 0.5, v = z / (2 uv_radius) + 0.5.
void cap(TessellatedShape& s, double inner, double outer, double y, bool up, int n,
         double uv_radius) {
  const auto uv = [&](glm::dvec3 p) {
    return glm::dvec2(p.x / (2.0 * uv_radius) + 0.5, p.z / (2.0 * uv_radius) + 0.5);
  };
  const int first = int(s.mesh.positions.size());
  for (int j = 0; j < n; ++j)
    vertex(s, ring_point(j, n, outer, y));
  for (int j = 0; inner > 0.0 && j < n; ++j)
    vertex(s, ring_point(j, n, inner, y));
  const int centre = inner > 0.0 ? -1 : vertex(s, {0.0, y, 0.0});
  const auto& p = s.mesh.positions;
  for (int j = 0; j < n; ++j) {
    const int o0 = first + j, o1 = first + (j + 1) % n;
    // Seen from +Y, increasing j turns counter-clockwise (from +Z towards +X): up-facing
    // triangles take o0 before o1, and the inner rim backwards.
    const int a = up ? o0 : o1, b = up ? o1 : o0;
    if (centre >= 0) {
      triangle(s, centre, a, b, uv(p[size_t(centre)]), uv(p[size_t(a)]), uv(p[size_t(b)]));
      continue;
    }
    const int i0 = o0 + n, i1 = o1 + n;
    const int c = up ? i1 : i0, d = up ? i0 : i1;
    triangle(s, a, b, c, uv(p[size_t(a)]), uv(p[size_t(b)]), uv(p[size_t(c)]));
    triangle(s, a, c, d, uv(p[size_t(a)]), uv(p[size_t(c)]), uv(p[size_t(d)]));
  }
}

/// A box of half extents `half`: six faces of their own vertices, each face's uv its two axes
/// (X faces (z, y), Y faces (x, z), Z faces (x, y)) mapped to [0, 1] across the box.
void box(TessellatedShape& s, glm::dvec3 half) {
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = axis == 0 ? 2 : 0, a2 = axis == 1 ? 2 : 1;
    for (const double side : {-1.0, 1.0}) {
      int corner[4];
      glm::dvec2 uv[4];
      const double su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
      for (int k = 0; k < 4; ++k) {
        glm::dvec3 p(0.0);
        p[axis] = side * half[axis];
        p[a1] = su[k] * half[a1];
        p[a2] = sv[k] * half[a2];
        corner[k] = vertex(s, p);
        uv[k] = {0.5 * su[k] + 0.5, 0.5 * sv[k] + 0.5};
      }
      // Counter-clockwise seen from outside: the corners' cross product along the outward axis.
      const glm::dvec3 e1 =
          s.mesh.positions[size_t(corner[1])] - s.mesh.positions[size_t(corner[0])];
      const glm::dvec3 e2 =
          s.mesh.positions[size_t(corner[2])] - s.mesh.positions[size_t(corner[0])];
      const bool ccw = glm::cross(e1, e2)[axis] * side > 0.0;
      const int order[6] = {0, 1, 2, 0, 2, 3};
      for (int t = 0; t < 2; ++t) {
        const int i = order[3 * t], j = order[3 * t + (ccw ? 1 : 2)],
                  k = order[3 * t + (ccw ? 2 : 1)];
        triangle(s, corner[i], corner[j], corner[k], uv[i], uv[j], uv[k]);
      }
    }
  }
}

}  // namespace

TessellatedShape tessellate_shape(const Shape& shape, int segments) {
  TessellatedShape s;
  const int n = segments;
  const double r = shape.radius, h = shape.height;
  switch (shape.type) {
    case ShapeType::kSphere:
      sphere(s, r, n);
      break;
    case ShapeType::kBox:
      box(s, 0.5 * glm::dvec3(shape.size));
      break;
    case ShapeType::kSlab:
      box(s, 0.5 * glm::dvec3(shape.size.x, shape.size.y, shape.thickness));
      break;
    case ShapeType::kCylinder:
      wall(s, r, h, n, true);
      cap(s, 0.0, r, 0.5 * h, true, n, r);
      cap(s, 0.0, r, -0.5 * h, false, n, r);
      break;
    case ShapeType::kHollowCylinder:
      wall(s, r, h, n, true);
      wall(s, r - shape.thickness, h, n, false);
      cap(s, r - shape.thickness, r, 0.5 * h, true, n, r);
      cap(s, r - shape.thickness, r, -0.5 * h, false, n, r);
      break;
    default:
      break;
  }
  return s;
}

}  // namespace gfield
