#include "preprocess/closest_point.hpp"

#include <tbb/parallel_for.h>

#include <limits>

namespace gfield {
namespace {

/// The query's mesh and the best point found so far (Embree hands it to every candidate).
struct Query {
  const TriangleMesh* mesh = nullptr;
  glm::dvec3 point{0.0};
  ClosestPoint best;
  double best_squared = std::numeric_limits<double>::infinity();
};

bool visit_triangle(RTCPointQueryFunctionArguments* args) {
  auto* query = static_cast<Query*>(args->userPtr);
  const glm::ivec3& t = query->mesh->triangles[args->primID];
  const std::vector<glm::dvec3>& p = query->mesh->positions;
  const glm::dvec2 uv = closest_barycentrics(query->point, p[t[0]], p[t[1]], p[t[2]]);
  const glm::dvec3 on = p[t[0]] + uv.x * (p[t[1]] - p[t[0]]) + uv.y * (p[t[2]] - p[t[0]]);
  const glm::dvec3 d = on - query->point;
  const double squared = glm::dot(d, d);
  if (squared >= query->best_squared) {
    return false;
  }
  query->best_squared = squared;
  query->best = {int(args->primID), uv.x, uv.y, std::sqrt(squared)};
  // Float BVH bounds: a triangle as near as the best is kept in the search.
  args->query->radius = float(query->best.distance) * (1.0f + 1e-6f) + 1e-30f;
  return true;
}

}  // namespace

glm::dvec2 closest_barycentrics(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b,
                                const glm::dvec3& c) {
  // Voronoi regions of the triangle (Ericson, Real-Time Collision Detection, 5.1.5).
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return {0.0, 0.0};
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
    return {1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 && d1 - d3 > 0.0)
    return {d1 / (d1 - d3), 0.0};
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
    return {0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 && d2 - d6 > 0.0)
    return {0.0, d2 / (d2 - d6)};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 && (d4 - d3) + (d5 - d6) > 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {1.0 - w, w};
  }
  // va + vb + vc = |ab x ac|^2; near zero (collinear corners, to rounding) the face region's
  // weights are noise: the nearest point of the three edges.
  const double sum = va + vb + vc;
  if (!(sum > 1e-10 * glm::dot(ab, ab) * glm::dot(ac, ac))) {
    glm::dvec2 best{0.0};
    double best_squared = std::numeric_limits<double>::infinity();
    const glm::dvec3 corner[3] = {a, b, c};
    const glm::dvec2 bary[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 e = corner[(k + 1) % 3] - corner[k];
      const double length2 = glm::dot(e, e);
      const double s =
          length2 > 0.0 ? glm::clamp(glm::dot(p - corner[k], e) / length2, 0.0, 1.0) : 0.0;
      const glm::dvec3 d = corner[k] + s * e - p;
      if (glm::dot(d, d) < best_squared) {
        best_squared = glm::dot(d, d);
        best = bary[k] + s * (bary[(k + 1) % 3] - bary[k]);
      }
    }
    return best;
  }
  return {vb / sum, vc / sum};
}

ClosestPoint closest_point(const EmbreeMesh& embree, const TriangleMesh& mesh,
                           const glm::dvec3& point) {
  if (mesh.triangles.empty())
    return {};
  Query query;
  query.mesh = &mesh;
  query.point = point;
  RTCPointQuery q;
  q.x = float(point.x);
  q.y = float(point.y);
  q.z = float(point.z);
  q.time = 0.0f;
  q.radius = std::numeric_limits<float>::infinity();
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(embree.scene(), &q, &context, visit_triangle, &query);
  return query.best;
}

std::vector<ClosestPoint> closest_points(const EmbreeMesh& embree, const TriangleMesh& mesh,
                                         const std::vector<glm::dvec3>& points) {
  std::vector<ClosestPoint> result(points.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size(), 256),
                    [&](const tbb::blocked_range<size_t>& range) {
                      for (size_t k = range.begin(); k != range.end(); ++k)
                        result[k] = closest_point(embree, mesh, points[k]);
                    });
  return result;
}

}  // namespace gfield
