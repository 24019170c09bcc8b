// Surface sampling and point-to-surface distances (Embree point queries, in parallel).

#include "preprocess/surface_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "preprocess/closest_point.hpp"
#include "preprocess/portable_random.hpp"

namespace gfield {
namespace {

const UnitUniform unit;

}  // namespace

std::vector<glm::dvec3> sample_surface(const TriangleMesh& mesh, size_t count, uint64_t seed) {
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0.0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3& t = mesh.triangles[f];
    total += 0.5 * glm::length(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                          mesh.positions[t[2]] - mesh.positions[t[0]]));
    cumulative[f] = total;
  }
  std::vector<glm::dvec3> points;
  if (!(total > 0.0))
    return points;
  points.reserve(count);
  std::mt19937_64 rng(seed);
  for (size_t k = 0; k < count; ++k) {
    const double r = unit(rng) * total;
    const size_t f = std::min(
        size_t(std::upper_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin()),
        cumulative.size() - 1);
    double a = unit(rng), b = unit(rng);
    if (a + b > 1.0)
      a = 1.0 - a, b = 1.0 - b;
    const glm::ivec3& t = mesh.triangles[f];
    points.push_back(mesh.positions[t[0]] + a * (mesh.positions[t[1]] - mesh.positions[t[0]]) +
                     b * (mesh.positions[t[2]] - mesh.positions[t[0]]));
  }
  return points;
}

std::vector<double> distances_to_surface(const std::vector<glm::dvec3>& points,
                                         const TriangleMesh& surface) {
  std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
  EmbreeMesh embree;
  std::string ignored;
  if (surface.triangles.empty() || !embree.build(surface, ignored, RTC_BUILD_QUALITY_LOW))
    return distance;
  const std::vector<ClosestPoint> closest = closest_points(embree, surface, points);
  for (size_t k = 0; k < points.size(); ++k)
    if (closest[k].triangle >= 0)
      distance[k] = closest[k].distance;
  return distance;
}

}  // namespace gfield
