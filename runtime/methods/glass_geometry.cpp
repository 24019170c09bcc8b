#include "runtime/methods/glass_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/analytic_primitives.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {
namespace {

int segments(float length, float max_edge) {
  return std::clamp(int(std::ceil(length / max_edge)), 1, 2048);
}

/// A (nu + 1) x (nv + 1) grid of f(u, v) for u, v in [0, 1].
template <class F>
void add_grid(TriangleSoup& soup, int nu, int nv, F f) {
  const unsigned base = unsigned(soup.vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      soup.vertices.push_back(f(float(i) / float(nu), float(j) / float(nv)));
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const unsigned a = base + unsigned(j * (nu + 1) + i);
      const unsigned b = a + 1, c = a + unsigned(nu + 1), d = c + 1;
      soup.indices.insert(soup.indices.end(), {a, b, d, a, d, c});
    }
  }
}

/// The faces of a box of half extents h, texture coordinates as the reference tracer's.
void add_box(TriangleSoup& soup, glm::vec3 h, float max_edge) {
  for (int axis = 0; axis < 3; ++axis) {
    const int a1 = axis == 0 ? 2 : 0;  // X faces: (z, y); Y faces: (x, z); Z faces: (x, y)
    const int a2 = axis == 1 ? 2 : 1;
    for (const float side : {-1.0f, 1.0f}) {
      add_grid(soup, segments(2.0f * h[a1], max_edge), segments(2.0f * h[a2], max_edge),
               [&](float u, float v) {
                 glm::vec3 p(0.0f), n(0.0f);
                 p[axis] = side * h[axis];
                 p[a1] = (u - 0.5f) * 2.0f * h[a1];
                 p[a2] = (v - 0.5f) * 2.0f * h[a2];
                 n[axis] = side;
                 return GpuVertex{p, n, {u, v}};
               });
    }
  }
}

}  // namespace

bool tessellate(const Shape& shape, float max_edge, TriangleSoup& soup) {
  switch (shape.type) {
    case ShapeType::kQuad:
      add_grid(soup, segments(shape.size.x, max_edge), segments(shape.size.y, max_edge),
               [&](float u, float v) {
                 return GpuVertex{{(u - 0.5f) * shape.size.x, (v - 0.5f) * shape.size.y, 0.0f},
                                  {0.0f, 0.0f, 1.0f},
                                  {u, v}};
               });
      return true;
    case ShapeType::kBox:
      add_box(soup, 0.5f * shape.size, max_edge);
      return true;
    case ShapeType::kSlab:
      add_box(soup, 0.5f * glm::vec3(shape.size.x, shape.size.y, shape.thickness), max_edge);
      return true;
    case ShapeType::kSphere: {
      const float r = shape.radius;
      add_grid(soup, segments(2.0f * gpu::GF_PI * r, max_edge), segments(gpu::GF_PI * r, max_edge),
               [&](float u, float v) {
                 const float a = 2.0f * gpu::GF_PI * (u - 0.5f), e = gpu::GF_PI * (v - 0.5f);
                 const glm::vec3 n(std::cos(e) * std::sin(a), std::sin(e),
                                   std::cos(e) * std::cos(a));
                 return GpuVertex{r * n, n, {u, v}};
               });
      return true;
    }
    case ShapeType::kCylinder: {
      const float r = shape.radius, h = shape.height;
      add_grid(soup, segments(2.0f * gpu::GF_PI * r, max_edge), segments(h, max_edge),
               [&](float u, float v) {
                 const float a = 2.0f * gpu::GF_PI * (u - 0.5f);
                 const glm::vec3 n(std::sin(a), 0.0f, std::cos(a));
                 return GpuVertex{{r * n.x, (v - 0.5f) * h, r * n.z}, n, {u, v}};
               });
      for (const float side : {-1.0f, 1.0f}) {
        add_grid(soup, segments(2.0f * gpu::GF_PI * r, max_edge), segments(r, max_edge),
                 [&](float u, float v) {
                   const float a = 2.0f * gpu::GF_PI * (u - 0.5f);
                   const glm::vec3 p(v * r * std::sin(a), side * 0.5f * h, v * r * std::cos(a));
                   return GpuVertex{
                       p, {0.0f, side, 0.0f}, {p.x / (2.0f * r) + 0.5f, p.z / (2.0f * r) + 0.5f}};
                 });
      }
      return true;
    }
    case ShapeType::kMesh:
    case ShapeType::kHollowCylinder:
      break;
  }
  return false;
}

void GlassSoup::triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 outward, float surface) {
  if (glm::dot(glm::cross(b - a, c - a), outward) < 0.0f)
    std::swap(b, c);
  for (const glm::vec3& p : {a, b, c})
    data.insert(data.end(), {p.x, p.y, p.z, surface});
}

GlassSoup glass_triangles(const SceneObject& object) {
  const glm::mat4 to_world(object_to_world(object.transform));
  const glm::mat3 normal_to_world = glm::transpose(glm::inverse(glm::mat3(to_world)));
  auto world = [&](glm::vec3 p) { return glm::vec3(to_world * glm::vec4(p, 1.0f)); };
  GlassSoup soup;
  const Shape& s = object.shape;
  if (s.type == ShapeType::kSlab) {
    const glm::vec3 h = 0.5f * glm::vec3(s.size.x, s.size.y, s.thickness);
    for (int axis = 0; axis < 3; ++axis) {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      const float surface = axis == 2 ? 0.0f : axis == 0 ? 1.0f : 2.0f;  // Z, X, Y pairs
      for (const float side : {-1.0f, 1.0f}) {
        glm::vec3 c[4];
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; ++k) {
          c[k][axis] = side * h[axis];
          c[k][a1] = corners[k][0] * h[a1];
          c[k][a2] = corners[k][1] * h[a2];
          c[k] = world(c[k]);
        }
        glm::vec3 n(0.0f);
        n[axis] = side;
        const glm::vec3 outward = normal_to_world * n;
        soup.triangle(c[0], c[1], c[2], outward, surface);
        soup.triangle(c[0], c[2], c[3], outward, surface);
      }
    }
    return soup;
  }
  // Hollow cylinder: outer wall (0), inner wall (1, its outward side faces the axis), rims (2).
  const int n = 256;
  const float outer = s.radius, inner = s.radius - s.thickness, h = 0.5f * s.height;
  for (int i = 0; i < n; ++i) {
    const float a0 = 2.0f * gpu::GF_PI * float(i) / float(n),
                a1 = 2.0f * gpu::GF_PI * float(i + 1) / float(n);
    const glm::vec3 r0(std::sin(a0), 0.0f, std::cos(a0)), r1(std::sin(a1), 0.0f, std::cos(a1));
    const glm::vec3 mid = normal_to_world * glm::normalize(r0 + r1);
    for (int wall = 0; wall < 2; ++wall) {
      const float r = wall == 0 ? outer : inner;
      const glm::vec3 outward = wall == 0 ? mid : -mid;
      const glm::vec3 p00 = world(r * r0 + glm::vec3(0, -h, 0)),
                      p10 = world(r * r1 + glm::vec3(0, -h, 0)),
                      p11 = world(r * r1 + glm::vec3(0, h, 0)),
                      p01 = world(r * r0 + glm::vec3(0, h, 0));
      soup.triangle(p00, p10, p11, outward, float(wall));
      soup.triangle(p00, p11, p01, outward, float(wall));
    }
    for (const float side : {-1.0f, 1.0f}) {
      const glm::vec3 y(0.0f, side * h, 0.0f);
      const glm::vec3 outward = normal_to_world * glm::vec3(0.0f, side, 0.0f);
      const glm::vec3 p00 = world(inner * r0 + y), p10 = world(outer * r0 + y),
                      p11 = world(outer * r1 + y), p01 = world(inner * r1 + y);
      soup.triangle(p00, p10, p11, outward, 2.0f);
      soup.triangle(p00, p11, p01, outward, 2.0f);
    }
  }
  return soup;
}

int glass_class(ShapeType shape, const std::vector<int>& codes, bool trace_verge) {
  const size_t count = std::min<size_t>(codes.size(), 4);
  if (count == 0)
    return 0;
  if (shape == ShapeType::kSlab) {
    if (count == 2 && codes[0] % 2 == 0 && codes[1] == codes[0] + 1)
      return 1 + codes[0] / 2;
    return -1;
  }
  if (count == 4 && codes[0] == 0 && codes[1] == 3 && codes[2] == 2 && codes[3] == 1)
    return 4;
  if (count == 2 && codes[0] == 0 && codes[1] == 1)
    return trace_verge ? -1 : 5;
  if (count == 2 && codes[0] == 0 && codes[1] == 3)
    return 6;
  if (count == 2 && codes[0] == 2 && codes[1] == 1)
    return 7;
  return -1;
}

std::vector<int> classes_present(const SceneObject& glass, const Camera& camera, float aspect,
                                 bool trace_verge) {
  // The straight eye lines of a grid of pixels against the exact glass: the same codes as the
  // peeling, hence the classes the frame needs.
  const glm::dmat4 to_world = object_to_world(glass.transform);
  const glm::dmat4 to_object = glm::inverse(to_world);
  std::set<int> classes = {0};
  const int n = 128;
  const int width = std::max(1, int(std::lround(n * aspect)));
  const double inner = double(glass.shape.radius) - double(glass.shape.thickness);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < width; ++x) {
      const CameraRay ray = camera_ray(camera, width, n, {x + 0.5, y + 0.5});
      const glm::dvec3 o(to_object * glm::dvec4(ray.origin, 1.0));
      const glm::dvec3 d(to_object * glm::dvec4(ray.direction, 0.0));
      std::vector<int> codes;
      double t_min = 0.0;
      PrimitiveHit hit;
      while (codes.size() < 4 && intersect_shape(glass.shape, o, d, t_min, 1e30, hit)) {
        const glm::dvec3 p = o + hit.t * d;
        int surface;
        if (glass.shape.type == ShapeType::kSlab) {
          const glm::dvec3 a = glm::abs(hit.normal);
          surface = a.z >= a.x && a.z >= a.y ? 0 : a.x >= a.y ? 1 : 2;
        } else if (std::abs(hit.normal.y) > 0.5) {
          surface = 2;
        } else {
          const double r = std::sqrt(p.x * p.x + p.z * p.z);
          surface = std::abs(r - inner) < std::abs(r - double(glass.shape.radius)) ? 1 : 0;
        }
        codes.push_back(2 * surface + (glm::dot(d, hit.normal) < 0.0 ? 0 : 1));
        t_min = hit.t * (1.0 + 1e-9) + 1e-9;
      }
      const int c = glass_class(glass.shape.type, codes, trace_verge);
      if (c >= 0)
        classes.insert(c);
    }
  }
  return {classes.begin(), classes.end()};
}

}  // namespace gfield
