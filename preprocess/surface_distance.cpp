// Surface sampling and point-to-surface distances (CGAL AABB tree, queries in parallel).

#include "preprocess/surface_distance.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace gfield {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using Triangle3 = Kernel::Triangle_3;
using Triangles = std::vector<Triangle3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

/// Uniform double in [0, 1) from 53 random bits.
double unit(std::mt19937_64& rng) {
  return double(rng() >> 11) * 0x1.0p-53;
}

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
  Triangles triangles;
  triangles.reserve(surface.triangles.size());
  auto point = [&](int v) {
    const glm::dvec3& p = surface.positions[v];
    return Point3(p.x, p.y, p.z);
  };
  for (const glm::ivec3& t : surface.triangles) {
    Triangle3 triangle(point(t[0]), point(t[1]), point(t[2]));
    if (!triangle.is_degenerate())
      triangles.push_back(triangle);
  }
  std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
  if (triangles.empty())
    return distance;
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 1024),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k != range.end(); ++k) {
                        const Point3 q(points[k].x, points[k].y, points[k].z);
                        distance[k] = std::sqrt(tree.squared_distance(q));
                      }
                    });
  return distance;
}

}  // namespace gfield
