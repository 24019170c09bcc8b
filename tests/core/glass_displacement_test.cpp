// Vertex displacement through glass (Mukai et al. 2013) against exact ray traces: the eye ray
// through the displaced vertex, refracted exactly (double precision, vector Snell) through the
// plate's two planes or the hollow cylinder's walls, must pass through the original vertex.

#include "gfield/glass_displacement.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace gfield {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSceneSize = 10.0;               // the scenes below fit in a 10-unit box
constexpr double kTolerance = 1e-4 * kSceneSize;  // the target

using glm::dvec3;

/// Vector Snell in double: unit `d` towards a surface with unit normal `m` facing it, eta = n1/n2.
bool refract_exact(dvec3 d, dvec3 m, double eta, dvec3& out) {
  const double cos_i = -glm::dot(d, m);
  const double k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
  if (k < 0.0)
    return false;
  out = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * m);
  return true;
}

double distance_to_line(dvec3 q, dvec3 origin, dvec3 direction) {
  const dvec3 rel = q - origin;
  return glm::length(rel - glm::dot(rel, direction) * direction);
}

// ------------------------------------------------------------------------------------- plate

/// The exact path from `eye` towards `through` across the plate's two planes; the final ray.
bool trace_plate(const GlassPlate& plate, dvec3 eye, dvec3 through, dvec3& origin, dvec3& dir) {
  dvec3 n = glm::normalize(dvec3(plate.normal));
  const dvec3 c(plate.centre);
  if (glm::dot(c - eye, n) < 0.0)
    n = -n;  // away from the eye
  dvec3 d = glm::normalize(through - eye);
  const double half = 0.5 * double(plate.thickness);
  // Front face, into the glass.
  const double t0 = glm::dot(c - half * n - eye, n) / glm::dot(d, n);
  const dvec3 p0 = eye + t0 * d;
  if (!refract_exact(d, -n, 1.0 / double(plate.ior), d))
    return false;
  const double t1 = glm::dot(c + half * n - p0, n) / glm::dot(d, n);
  const dvec3 p1 = p0 + t1 * d;
  if (!refract_exact(d, -n, double(plate.ior), d))
    return false;
  origin = p1;
  dir = d;
  return t0 > 0.0 && t1 > 0.0;
}

TEST(GlassDisplacement, PlateEquationFiveRootSatisfiesTheEquation) {
  for (const double n : {1.33, 1.5, 1.9}) {
    for (const double w : {0.2, 1.0}) {
      for (const double x : {0.0, 0.3, 2.0, 8.0}) {
        const double y = 5.0;
        const double s = plate_incidence_sine(float(x), float(y), float(w), float(n));
        const double theta = std::asin(s);
        const double phi = std::asin(s / n);
        EXPECT_NEAR((y - w) * std::tan(theta) + w * std::tan(phi), x, 1e-5 * (1.0 + x))
            << "n " << n << " w " << w << " x " << x;
      }
    }
  }
}

TEST(GlassDisplacement, PlateVertexSeenWhereTheExactRayGoes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const dvec3 eye(0.0, 1.6, 8.0);
  int checked = 0;
  // Inclinations about Y as in the paper's Figure 9, and oblique 3D orientations.
  const std::vector<dvec3> axes = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0},
                                   {0, 1, 0}, {1, 1, 0}, {1, 2, 3}};
  const std::vector<double> angles = {0.0, 5.0, 30.0, 60.0, 40.0, 70.0};
  for (size_t a = 0; a < axes.size(); ++a) {
    for (const float w : {0.2f, 1.0f}) {
      const glm::dmat3 rotation(
          glm::rotate(glm::dmat4(1.0), angles[a] * kPi / 180.0, glm::normalize(axes[a])));
      GlassPlate plate;
      plate.centre = glm::vec3(1.2f, 1.3f, 1.0f);
      plate.normal = glm::vec3(rotation * dvec3(0, 0, 1));
      plate.thickness = w;
      plate.ior = 1.5f;
      for (int k = 0; k < 20;) {
        const dvec3 q(2.0 * unit(rng), 1.3 + 1.5 * unit(rng), -1.5 + 1.5 * unit(rng));
        const dvec3 away = glm::dot(dvec3(plate.centre) - eye, dvec3(plate.normal)) > 0.0
                               ? dvec3(plate.normal)
                               : -dvec3(plate.normal);
        if (glm::dot(q - dvec3(plate.centre), away) <= 0.5 * double(w))
          continue;  // not behind the plate
        ++k;
        const glm::vec3 seen = plate_displace(plate, glm::vec3(eye), glm::vec3(q));
        dvec3 origin, dir;
        ASSERT_TRUE(trace_plate(plate, eye, dvec3(seen), origin, dir));
        EXPECT_LT(distance_to_line(q, origin, dir), kTolerance)
            << "angle " << angles[a] << " w " << w << " vertex " << q.x << " " << q.y << " " << q.z;
        // Moved along the normal only (equation 2), and by less than the thickness.
        const dvec3 move = dvec3(seen) - q;
        const dvec3 n = glm::normalize(dvec3(plate.normal));
        EXPECT_LT(glm::length(move - glm::dot(move, n) * n), 1e-5 * kSceneSize);
        EXPECT_LE(std::abs(glm::dot(move, n)), double(w) * (1.0 + 1e-5));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 240);
}

TEST(GlassDisplacement, PlateVertexInsideTheGlassSeenThroughTheNearFace) {
  GlassPlate plate;
  plate.centre = glm::vec3(0.0f, 0.0f, 0.0f);
  plate.normal = glm::vec3(0.0f, 0.0f, 1.0f);
  plate.thickness = 0.5f;
  const dvec3 eye(0.0, 0.3, 5.0);
  for (const dvec3 q : {dvec3(0.8, -0.4, 0.1), dvec3(1.5, 0.7, -0.2), dvec3(0.0, 0.3, 0.0)}) {
    const glm::vec3 seen = plate_displace(plate, glm::vec3(eye), glm::vec3(q));
    // Exact: the eye ray through `seen` refracted once at the near face z = 0.25 reaches q.
    dvec3 d = glm::normalize(dvec3(seen) - eye);
    const dvec3 p = eye + (0.25 - eye.z) / d.z * d;
    ASSERT_TRUE(refract_exact(d, dvec3(0, 0, 1), 1.0 / 1.5, d));
    EXPECT_LT(distance_to_line(q, p, d), kTolerance) << q.x << " " << q.y << " " << q.z;
  }
}

TEST(GlassDisplacement, PlateLeavesVerticesInFrontUnchanged) {
  GlassPlate plate;
  plate.centre = glm::vec3(0.0f, 0.0f, 0.0f);
  plate.normal = glm::vec3(0.0f, 0.0f, 1.0f);
  plate.thickness = 0.5f;
  const glm::vec3 eye(0.0f, 0.0f, 5.0f);
  for (const glm::vec3 v : {glm::vec3(0.3f, 0.1f, 1.0f), glm::vec3(0.3f, 0.1f, 0.25f)}) {
    const glm::vec3 seen = plate_displace(plate, eye, v);
    EXPECT_EQ(seen, v);
  }
  // Behind: moved towards the eye by W (1 - 1/n) on the axis.
  const glm::vec3 seen = plate_displace(plate, eye, glm::vec3(0.0f, 0.0f, -2.0f));
  EXPECT_NEAR(seen.z, -2.0f + 0.5f * (1.0f - 1.0f / 1.5f), 1e-6f);
}

// ---------------------------------------------------------------------------------- cylinder

struct Hollow {
  double outer = 1.0, inner = 0.92, height = 2.2, ior = 1.5;
};

/// The natural exact path of a ray through a hollow cylinder with open ends (walls only, within
/// |y| <= height / 2): the nearest wall crossing each time. Returns the sequence of surfaces
/// met (0 outer, 1 inner; + 10 for a total internal reflection) and the final ray.
std::vector<int> trace_hollow(const Hollow& h, dvec3 o, dvec3 d, dvec3& origin, dvec3& dir) {
  std::vector<int> surfaces;
  double index = 1.0;
  for (int event = 0; event < 8; ++event) {
    double best = 1e300;
    int surface = -1;
    for (int s = 0; s < 2; ++s) {
      const double r = s == 0 ? h.outer : h.inner;
      const double a = d.x * d.x + d.z * d.z, b = o.x * d.x + o.z * d.z,
                   c = o.x * o.x + o.z * o.z - r * r;
      const double disc = b * b - a * c;
      if (a == 0.0 || disc < 0.0)
        continue;
      for (const double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a}) {
        if (t > 1e-9 && t < best && std::abs(o.y + t * d.y) <= 0.5 * h.height) {
          best = t;
          surface = s;
        }
      }
    }
    if (surface < 0)
      break;
    o = o + best * d;
    const dvec3 outward = glm::normalize(dvec3(o.x, 0.0, o.z));
    const dvec3 m = glm::dot(d, outward) < 0.0 ? outward : -outward;
    const double next = index == 1.0 ? h.ior : 1.0;
    if (refract_exact(d, m, index / next, d)) {
      index = next;
      surfaces.push_back(surface);
    } else {  // total internal reflection
      d = d - 2.0 * glm::dot(d, m) * m;
      surfaces.push_back(10 + surface);
    }
  }
  origin = o;
  dir = d;
  return surfaces;
}

struct CylinderCase {
  CylinderPath path;
  std::vector<int> surfaces;  ///< the sequence the exact trace must take
};

/// Random eye rays whose exact path has the sequence of `c`; a vertex placed along the final ray
/// must be displaced onto the eye ray, and the exact trace through the displaced vertex must
/// reach it.
void check_cylinder_case(const CylinderCase& c, dvec3 eye, double spread, int wanted) {
  const Hollow h;
  GlassCylinder cylinder;
  cylinder.outer_radius = float(h.outer);
  cylinder.inner_radius = float(h.inner);
  cylinder.ior = float(h.ior);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> beyond(0.2, 3.0);
  const dvec3 look = glm::normalize(dvec3(0.0, 0.0, 0.0) - eye);
  const dvec3 right = glm::normalize(glm::cross(look, dvec3(0, 1, 0)));
  const dvec3 up = glm::cross(right, look);
  int checked = 0;
  for (int attempt = 0; attempt < 20000 && checked < wanted; ++attempt) {
    const dvec3 d = glm::normalize(look + spread * (unit(rng) * right + unit(rng) * up));
    dvec3 origin, dir;
    if (trace_hollow(h, eye, d, origin, dir) != c.surfaces)
      continue;
    // Inside the glass for a front-wall path, else beyond the cylinder.
    const double reach = c.path == CylinderPath::kFrontWall ? 0.8 * beyond(rng) / 3.0 : beyond(rng);
    const dvec3 q = origin + reach * dir;
    if (c.path == CylinderPath::kFrontWall && q.x * q.x + q.z * q.z >= h.inner * h.inner)
      continue;
    glm::vec3 seen;
    ASSERT_TRUE(cylinder_displace(cylinder, c.path, glm::vec3(eye), glm::vec3(q), seen))
        << "path " << int(c.path) << " vertex " << q.x << " " << q.y << " " << q.z;
    // On the exact eye ray that reaches q, ...
    EXPECT_LT(distance_to_line(dvec3(seen), eye, d), kTolerance)
        << "path " << int(c.path) << " vertex " << q.x << " " << q.y << " " << q.z;
    // ... and the exact trace through it takes the same interfaces and reaches q (up to the
    // float direction's error times the path's magnification, large at the verge's grazing
    // reflections).
    dvec3 o2, d2;
    const dvec3 toward = glm::normalize(dvec3(seen) - eye);
    EXPECT_EQ(trace_hollow(h, eye, toward, o2, d2), c.surfaces);
    EXPECT_LT(distance_to_line(q, o2, d2),
              c.path == CylinderPath::kVerge ? 10.0 * kTolerance : kTolerance)
        << "path " << int(c.path) << " vertex " << q.x << " " << q.y << " " << q.z;
    ++checked;
  }
  EXPECT_EQ(checked, wanted) << "path " << int(c.path);
}

TEST(GlassDisplacement, CylinderBothWallsFourRefractions) {
  check_cylinder_case({CylinderPath::kBothWalls, {0, 1, 1, 0}}, {0.0, 0.5, 6.0}, 0.15, 40);
}

TEST(GlassDisplacement, CylinderVergeTwoRefractions) {
  // Two refractions and the total internal reflection at the inner surface between them.
  check_cylinder_case({CylinderPath::kVerge, {0, 11, 0}}, {0.0, 0.5, 6.0}, 0.18, 40);
}

TEST(GlassDisplacement, CylinderFrontWallIntoTheInterior) {
  check_cylinder_case({CylinderPath::kFrontWall, {0, 1}}, {0.0, 0.5, 6.0}, 0.15, 40);
}

TEST(GlassDisplacement, CylinderBackWallSeenThroughTheOpenTop) {
  check_cylinder_case({CylinderPath::kBackWall, {1, 0}}, {0.0, 4.0, 1.5}, 0.5, 40);
}

TEST(GlassDisplacement, CylinderVirtualPointMatchesThePlateForAThinFlatPatch) {
  // Far from the axis a wall is locally flat: the eq. 6-8 chain for a huge cylinder agrees
  // with the plate's equation 2 (two independent routes to the same point).
  GlassCylinder cylinder;
  cylinder.outer_radius = 100.0f;
  cylinder.inner_radius = 99.5f;
  GlassPlate plate;
  plate.centre = glm::vec3(0.0f, 0.0f, 99.75f);
  plate.normal = glm::vec3(0.0f, 0.0f, 1.0f);
  plate.thickness = 0.5f;
  const glm::vec3 eye(0.0f, 0.0f, 103.0f);
  const glm::vec3 q(0.1f, 0.3f, 97.0f);
  glm::vec3 seen;
  ASSERT_TRUE(cylinder_displace(cylinder, CylinderPath::kFrontWall, eye, q, seen));
  const glm::vec3 expected = plate_displace(plate, eye, q);
  EXPECT_LT(glm::length(seen - expected), 2e-3f);
}

TEST(GlassDisplacement, CylinderRejectsVerticesNoPathReaches) {
  GlassCylinder cylinder;
  glm::vec3 seen;
  // In front of the cylinder: no refracted path ends there.
  EXPECT_FALSE(cylinder_displace(cylinder, CylinderPath::kBothWalls, glm::vec3(0, 0, 6),
                                 glm::vec3(0.0f, 0.0f, 3.0f), seen));
  EXPECT_EQ(seen, glm::vec3(0.0f, 0.0f, 3.0f));
}

}  // namespace
}  // namespace gfield
