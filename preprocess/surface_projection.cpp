#include "preprocess/surface_projection.hpp"

#include <tbb/parallel_for.h>

#include "geometry/outward_normals.hpp"
#include "preprocess/closest_point.hpp"

namespace gfield {

bool SurfaceProjection::build(const TriangleMesh& input, const MeshAppearance* appearance,
                              const TriangleMesh& welded, double reach, std::string& error) {
  reach_ = reach;
  input_ = &input;
  appearance_ = appearance != nullptr && carries_base_color(*appearance) ? appearance : nullptr;
  welded_ = &welded;
  normals_ = angle_weighted_vertex_normals(welded);
  return embree_.build(welded, error);
}

namespace {

/// The point of the surface that the texel at `p` with the proxy's normal `n` stands for: the
/// nearest crossing of the line p + t n within |t| <= reach (triangle -1: none).
ClosestPoint line_crossing(const EmbreeMesh& embree, glm::dvec3 p, glm::dvec3 n, double reach) {
  ClosestPoint best;
  for (const double side : {1.0, -1.0}) {
    const RayHit hit = intersect(embree, glm::vec3(p), glm::vec3(side * n), 0.0f, float(reach));
    if (hit.hit && (best.triangle < 0 || double(hit.t) < best.distance))
      best = {hit.triangle, double(hit.u), double(hit.v), double(hit.t)};
  }
  return best;
}

}  // namespace

glm::vec3 SurfaceProjection::base_color(const ClosestPoint& c) const {
  return footprint_color(*input_, *appearance_, size_t(c.triangle),
                         glm::dvec3(1.0 - c.u - c.v, c.u, c.v), glm::vec2(0.0f), glm::vec2(0.0f));
}

void SurfaceProjection::project(GeometryImage& image) const {
  std::vector<size_t> texels;
  for (size_t t = 0; t < image.coverage.size(); ++t)
    if (image.coverage[t] > 0.0f)
      texels.push_back(t);
  if (appearance_ != nullptr)
    image.albedo.assign(image.coverage.size(), glm::vec3(0.0f));
  tbb::parallel_for(size_t(0), texels.size(), [&](size_t k) {
    const size_t texel = texels[k];
    const glm::dvec3 point(image.position[texel]);
    ClosestPoint c = line_crossing(embree_, point, glm::dvec3(image.normal[texel]), reach_);
    if (c.triangle < 0) {  // else the closest point, where it lies within reach
      const ClosestPoint closest = closest_point(embree_, *welded_, point);
      if (appearance_ != nullptr && closest.triangle >= 0)
        image.albedo[texel] = base_color(closest);
      if (closest.triangle < 0 || closest.distance > reach_)
        return;  // keeps the proxy's point (faces that fill holes)
      c = closest;
    }
    const glm::ivec3& t = welded_->triangles[size_t(c.triangle)];
    const glm::dvec3 w(1.0 - c.u - c.v, c.u, c.v);
    const std::vector<glm::dvec3>& p = welded_->positions;
    image.position[texel] = glm::vec3(w.x * p[t[0]] + w.y * p[t[1]] + w.z * p[t[2]]);
    glm::dvec3 n = w.x * normals_[t[0]] + w.y * normals_[t[1]] + w.z * normals_[t[2]];
    if (!(glm::length(n) > 0.0))
      n = glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
    if (glm::length(n) > 0.0) {
      n = glm::normalize(n);
      // The original's winding may disagree with the repaired proxy's orientation.
      image.normal[texel] = glm::vec3(glm::dot(n, glm::dvec3(image.normal[texel])) < 0.0 ? -n : n);
    }
    if (appearance_ != nullptr)
      image.albedo[texel] = base_color(c);
  });
}

}  // namespace gfield
