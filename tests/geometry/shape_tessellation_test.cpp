// Analytic shapes tessellated for `gfield export-gltf` (geometry/shape_tessellation.hpp),
// measured against the shapes themselves: every vertex on the exact surface, the enclosed volume
// against the shape's (4/3 pi r^3, pi r^2 h, ...) within the inscribed polygon's deficit, every
// face wound outwards, every corner's texture coordinates those the reference tracer computes at
// that point (geometry/analytic_primitives.hpp, found by casting a ray at it), sharp edges split.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/analytic_primitives.hpp"
#include "geometry/outward_normals.hpp"
#include "geometry/shape_tessellation.hpp"

namespace gfield {
namespace {

Shape shape_of(ShapeType type) {
  Shape s;
  s.type = type;
  s.radius = 1.5f;
  s.height = 2.5f;
  s.size = glm::vec3(2.0f, 3.0f, 0.5f);
  s.thickness = 0.25f;
  return s;
}

double signed_volume(const TriangleMesh& m) {
  double v = 0.0;
  for (const glm::ivec3& t : m.triangles)
    v += glm::dot(m.positions[size_t(t.x)],
                  glm::cross(m.positions[size_t(t.y)], m.positions[size_t(t.z)])) /
         6.0;
  return v;
}

/// The shape's exact volume.
double exact_volume(const Shape& s) {
  const double pi = 3.14159265358979323846, r = s.radius, h = s.height;
  switch (s.type) {
    case ShapeType::kSphere:
      return 4.0 / 3.0 * pi * r * r * r;
    case ShapeType::kBox:
      return double(s.size.x) * s.size.y * s.size.z;
    case ShapeType::kSlab:
      return double(s.size.x) * s.size.y * s.thickness;
    case ShapeType::kCylinder:
      return pi * r * r * h;
    default:  // hollow cylinder
      return pi * (r * r - (r - s.thickness) * (r - s.thickness)) * h;
  }
}

/// How far outside a face the rays of hit_at start.
constexpr double kOffset = 0.05;

/// The tracer's hit near object point `p` of a face whose outward normal is `face_normal`: the
/// ray from kOffset outside the face back along the normal.
PrimitiveHit hit_at(const Shape& shape, glm::dvec3 p, glm::dvec3 face_normal) {
  PrimitiveHit hit;
  const glm::dvec3 origin = p + kOffset * face_normal;
  EXPECT_TRUE(intersect_shape(shape, origin, -face_normal, 0.0, 1.0, hit));
  return hit;
}

class Tessellation : public ::testing::TestWithParam<ShapeType> {};

TEST_P(Tessellation, LiesOnTheShapeEnclosesItsVolumeFacesOutAndCarriesItsTextureCoordinates) {
  const Shape shape = shape_of(GetParam());
  const int n = 64;
  const TessellatedShape t = tessellate_shape(shape, n);
  ASSERT_FALSE(t.mesh.triangles.empty());
  ASSERT_EQ(t.corner_uv.size(), 3 * t.mesh.triangles.size());
  // The inscribed polygon loses at most 1 - cos(pi / n) of a radius (0.12% at 64) in each
  // direction that is round: the volume 2 (cylinders) or 3 (spheres) times that, within 4 times.
  const double exact = exact_volume(shape), volume = signed_volume(t.mesh);
  EXPECT_GT(volume, 0.0) << "wound inwards";
  EXPECT_NEAR(volume / exact, 1.0, 4.0 * (1.0 - std::cos(3.14159265 / n)));
  for (size_t f = 0; f < t.mesh.triangles.size(); ++f) {
    const glm::ivec3 tri = t.mesh.triangles[f];
    const glm::dvec3 a = t.mesh.positions[size_t(tri.x)], b = t.mesh.positions[size_t(tri.y)],
                     c = t.mesh.positions[size_t(tri.z)];
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = t.mesh.positions[size_t(tri[k])];
      const glm::dvec3 inside = glm::mix(p, (a + b + c) / 3.0, 1e-3);  // within the face
      const PrimitiveHit hit = hit_at(shape, inside, normal);
      // The face's normal is the surface's there (within the facet's turn, 2 pi / n) and the
      // tracer finds the surface at the corner (within the sagitta).
      ASSERT_GT(glm::dot(hit.normal, normal), std::cos(2.0 * 6.2831853 / n)) << "face " << f;
      ASSERT_NEAR(hit.t, kOffset, 2.0 * (1.0 - std::cos(3.14159265 / n)) * shape.radius + 1e-6);
      // Texture coordinates: the tracer's at the corner, u wrapping at the seam; a pole's u is
      // free (the tracer's is atan2(0, 0)).
      const glm::vec2 uv = t.corner_uv[3 * f + size_t(k)];
      const bool pole =
          shape.type == ShapeType::kSphere && std::abs(std::abs(p.y) - shape.radius) < 1e-9;
      const double du = std::abs(uv.x - hit.uv.x);
      if (!pole) {
        EXPECT_LT(std::min(du, 1.0 - du), 0.02) << "face " << f << " corner " << k;
      }
      EXPECT_NEAR(uv.y, hit.uv.y, 0.02) << "face " << f << " corner " << k;
    }
  }
}

TEST_P(Tessellation, SmoothSurfacesShareVerticesAndSharpEdgesSplitThem) {
  const Shape shape = shape_of(GetParam());
  const TessellatedShape t = tessellate_shape(shape, 32);
  // The reference tracer's vertex normals are the surface's: radial on round surfaces (the
  // seam and the poles included), axis-aligned on flat faces and caps.
  const std::vector<glm::dvec3> normals = outward_vertex_normals(t.mesh);
  for (size_t f = 0; f < t.mesh.triangles.size(); ++f) {
    const glm::ivec3 tri = t.mesh.triangles[f];
    const glm::dvec3 a = t.mesh.positions[size_t(tri.x)], b = t.mesh.positions[size_t(tri.y)],
                     c = t.mesh.positions[size_t(tri.z)];
    const glm::dvec3 centre = (a + b + c) / 3.0;
    const glm::dvec3 face = glm::normalize(glm::cross(b - a, c - a));
    for (int k = 0; k < 3; ++k) {
      const PrimitiveHit hit =
          hit_at(shape, glm::mix(t.mesh.positions[size_t(tri[k])], centre, 1e-6), face);
      EXPECT_GT(glm::dot(normals[size_t(tri[k])], hit.normal), std::cos(0.02))
          << "face " << f << " corner " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, Tessellation,
                         ::testing::Values(ShapeType::kSphere, ShapeType::kBox,
                                           ShapeType::kCylinder, ShapeType::kSlab,
                                           ShapeType::kHollowCylinder),
                         [](const auto& info) {
                           std::string name = shape_name(info.param);
                           name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                           return name;
                         });

}  // namespace
}  // namespace gfield
