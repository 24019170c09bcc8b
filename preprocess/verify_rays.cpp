// The ray families of `gfield verify`: segments through the box, view rays, and rays leaving a
// mesh's surface (random, and mirror reflections), from portable random numbers.

#include "preprocess/verify_rays.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/outward_normals.hpp"
#include "gfield/box.hpp"
#include "preprocess/portable_random.hpp"

namespace gfield {
namespace {

/// Uniform point on face `face` of the unit cube.
glm::vec3 random_face_point(std::mt19937_64& rng, int face) {
  const UnitUniformFloat unit;
  const float s = unit(rng);
  const float t = unit(rng);
  return face_point(face, glm::vec2(s, t));
}

/// Unit vector uniform on the sphere.
glm::vec3 random_direction(std::mt19937_64& rng) {
  const StandardNormal gauss;
  glm::vec3 g(gauss(rng), gauss(rng), gauss(rng));
  while (glm::dot(g, g) < 1e-12f) {
    g = glm::vec3(gauss(rng), gauss(rng), gauss(rng));
  }
  return glm::normalize(g);
}

/// Unit normal of triangle f as wound.
glm::vec3 face_normal(const TriangleMesh& mesh, int f) {
  const glm::ivec3 t = mesh.triangles[size_t(f)];
  const glm::dvec3 n = glm::cross(mesh.positions[size_t(t[1])] - mesh.positions[size_t(t[0])],
                                  mesh.positions[size_t(t[2])] - mesh.positions[size_t(t[0])]);
  return glm::length(n) > 0.0 ? glm::vec3(glm::normalize(n)) : glm::vec3(0.0f);
}

}  // namespace

std::vector<Ray> random_box_rays(const Box& box, size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const UniformInt face{0, 5};
  const UniformInt other{1, 5};
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    const int entry_face = face(rng);
    const int exit_face = (entry_face + other(rng)) % 6;
    const glm::vec3 entry = from_unit_cube(box, random_face_point(rng, entry_face));
    const glm::vec3 exit = from_unit_cube(box, random_face_point(rng, exit_face));
    ray.origin = entry;
    ray.direction = exit - entry;
    ray.t_min = 0.0f;
    ray.t_max = 1.0f;
  }
  return rays;
}

std::vector<Ray> random_view_rays(const Box& box, size_t count, uint64_t seed) {
  std::mt19937_64 rng(seed);
  const StandardNormal gauss;
  const UnitUniformFloat unit;
  const glm::vec3 centre = 0.5f * (box.min + box.max);
  const float radius = diagonal(box);
  std::vector<Ray> rays(count);
  for (Ray& ray : rays) {
    glm::vec3 g(gauss(rng), gauss(rng), gauss(rng));
    while (glm::dot(g, g) < 1e-12f) {
      g = glm::vec3(gauss(rng), gauss(rng), gauss(rng));
    }
    const glm::vec3 eye = centre + radius * glm::normalize(g);
    const glm::vec3 target = from_unit_cube(box, glm::vec3(unit(rng), unit(rng), unit(rng)));
    ray.origin = eye;
    ray.direction = glm::normalize(target - eye);
    ray.t_min = 0.0f;
    ray.t_max = gpu::GF_FAR;
  }
  return rays;
}

SurfaceOffsets surface_offsets(const GeometryImage& image, const Box& box) {
  return {kMinRayOffset * diagonal(box), image.ray_offset * diagonal(box)};
}

SurfaceRays random_surface_rays(const TriangleMesh& mesh, size_t count, SurfaceOffsets offsets,
                                uint64_t seed) {
  std::vector<double> cumulative(mesh.triangles.size());
  double area = 0.0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::ivec3 t = mesh.triangles[f];
    area +=
        0.5 * glm::length(glm::cross(mesh.positions[size_t(t[1])] - mesh.positions[size_t(t[0])],
                                     mesh.positions[size_t(t[2])] - mesh.positions[size_t(t[0])]));
    cumulative[f] = area;
  }
  const float outward = float(outward_orientation(mesh));
  std::mt19937_64 rng(seed);
  const UnitUniform unit;
  SurfaceRays out;
  out.self_t_min = 2.0f * offsets.self;
  for (size_t i = 0; i < count && area > 0.0; ++i) {
    const size_t f =
        size_t(std::upper_bound(cumulative.begin(), cumulative.end(), unit(rng) * area) -
               cumulative.begin());
    const int face = int(std::min(f, cumulative.size() - 1));
    const glm::ivec3 t = mesh.triangles[size_t(face)];
    const double r = std::sqrt(unit(rng));
    const double b = unit(rng);
    const glm::dvec3 p = (1.0 - r) * mesh.positions[size_t(t[0])] +
                         r * (1.0 - b) * mesh.positions[size_t(t[1])] +
                         r * b * mesh.positions[size_t(t[2])];
    glm::vec3 d = random_direction(rng);
    const glm::vec3 g = outward * face_normal(mesh, face);
    if (glm::dot(d, g) < 0.0f) {
      d = -d;
    }
    out.rays.push_back({glm::vec3(p) + offsets.path * g, d, 2.0f * offsets.path, gpu::GF_FAR});
    out.self_origins.push_back(glm::vec3(p) + offsets.self * g);
    out.facing.push_back(outward);
    out.triangles.push_back(face);
  }
  return out;
}

namespace {

/// The smooth normal at hit `h` (angle-weighted vertex `normals` interpolated), `g` where those
/// cancel.
glm::vec3 smooth_normal(const TriangleMesh& mesh, const std::vector<glm::dvec3>& normals,
                        const RayHit& h, glm::vec3 g) {
  const glm::ivec3 t = mesh.triangles[size_t(h.triangle)];
  const glm::dvec3 smooth = (1.0 - h.u - h.v) * normals[size_t(t[0])] +
                            double(h.u) * normals[size_t(t[1])] +
                            double(h.v) * normals[size_t(t[2])];
  return glm::length(smooth) > 0.0 ? glm::vec3(glm::normalize(smooth)) : g;
}

/// Exact first hits of `rays` on `embree`'s mesh (ray i ignores triangle ignored[i] when given).
std::vector<RayHit> exact_hits(const EmbreeMesh& embree, const std::vector<Ray>& rays,
                               const std::vector<int>& ignored) {
  std::vector<RayHit> hits(rays.size());
  tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) {
    hits[i] = intersect(embree, rays[i].origin, rays[i].direction, rays[i].t_min, rays[i].t_max,
                        ignored.empty() ? -1 : ignored[i]);
  });
  return hits;
}

/// The rays that leave the exact first hits of `rays` on `mesh` (a ray i with ignored[i] >= 0
/// leaves that triangle), up to `count`: reflected about the smooth normal (angle-weighted vertex
/// normals; about the face's normal where that would leave below the face), or with `eta` > 0
/// refracted through the surface (eta: the index of refraction on the ray's side over the one
/// beyond; reflected where the refraction is total).
SurfaceRays rays_leaving_hits(const EmbreeMesh& embree, const TriangleMesh& mesh,
                              const std::vector<Ray>& rays, const std::vector<int>& ignored,
                              size_t count, SurfaceOffsets offsets, float eta) {
  const std::vector<glm::dvec3> normals = angle_weighted_vertex_normals(mesh);
  const std::vector<RayHit> hits = exact_hits(embree, rays, ignored);
  SurfaceRays out;
  out.self_t_min = 2.0f * offsets.self;
  for (size_t i = 0; i < rays.size() && out.rays.size() < count; ++i) {
    const RayHit& h = hits[i];
    const glm::vec3 origin = rays[i].origin + h.t * rays[i].direction;
    if (!h.hit ||
        !std::isfinite(origin.x + origin.y + origin.z)) {  // t overflows at the 1e15 limit
      continue;
    }
    const glm::vec3 d = glm::normalize(rays[i].direction);
    glm::vec3 g = face_normal(mesh, h.triangle);
    g = glm::dot(d, g) < 0.0f ? g : -g;
    glm::vec3 n = smooth_normal(mesh, normals, h, g);
    n = glm::dot(d, n) < 0.0f ? n : -n;
    glm::vec3 r = eta > 0.0f ? glm::refract(d, n, eta) : glm::vec3(0.0f);
    if (eta > 0.0f && glm::dot(r, r) > 0.0f && glm::dot(r, g) < 0.0f) {
      g = -g;  // through the surface
    } else {
      r = glm::reflect(d, n);
      if (glm::dot(r, g) <= 0.0f) {
        r = glm::reflect(d, g);
      }
    }
    r = glm::normalize(r);
    out.rays.push_back({origin + offsets.path * g, r, 2.0f * offsets.path, gpu::GF_FAR});
    out.self_origins.push_back(origin + offsets.self * g);
    out.facing.push_back(glm::dot(face_normal(mesh, h.triangle), g) >= 0.0f ? 1.0f : -1.0f);
    out.triangles.push_back(h.triangle);
  }
  return out;
}

}  // namespace

SurfaceRays mirror_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                                size_t count, SurfaceOffsets offsets, uint64_t seed) {
  return rays_leaving_hits(embree, mesh, random_view_rays(box, 4 * count, seed), {}, count, offsets,
                           0.0f);
}

SurfaceRays glass_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                               size_t count, SurfaceOffsets offsets, uint64_t seed, float ior) {
  return rays_leaving_hits(embree, mesh, random_view_rays(box, 4 * count, seed), {}, count, offsets,
                           1.0f / ior);
}

SurfaceRays glass_inside_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                              size_t count, SurfaceOffsets offsets, uint64_t seed, float ior) {
  const SurfaceRays into = glass_surface_rays(embree, mesh, box, 2 * count, offsets, seed, ior);
  return rays_leaving_hits(embree, mesh, into.rays, into.triangles, count, offsets, ior);
}

SurfaceRays shadow_surface_rays(const EmbreeMesh& embree, const TriangleMesh& mesh, const Box& box,
                                size_t count, SurfaceOffsets offsets, uint64_t seed) {
  const std::vector<Ray> view = random_view_rays(box, 4 * count, seed);
  const std::vector<RayHit> hits = exact_hits(embree, view, {});
  const std::vector<glm::dvec3> normals = angle_weighted_vertex_normals(mesh);
  const float offset = std::max(offsets.self, 10.0f * offsets.path);
  std::mt19937_64 rng(seed + 1);
  SurfaceRays out;
  out.self_t_min = 2.0f * offset;
  out.any_hit = true;
  for (size_t i = 0; i < view.size() && out.rays.size() < count; ++i) {
    const RayHit& h = hits[i];
    const glm::vec3 l = random_direction(rng);
    if (!h.hit) {
      continue;
    }
    const glm::vec3 face = face_normal(mesh, h.triangle);
    const glm::vec3 g = glm::dot(view[i].direction, face) < 0.0f ? face : -face;
    glm::vec3 n = smooth_normal(mesh, normals, h, g);
    n = glm::dot(view[i].direction, n) < 0.0f ? n : -n;
    if (glm::dot(l, g) <= 0.0f || glm::dot(l, n) <= 0.0f) {
      continue;  // the light is behind the surface: no shadow ray
    }
    const glm::vec3 origin = view[i].origin + h.t * view[i].direction + offset * g;
    out.rays.push_back({origin, l, 2.0f * offset, gpu::GF_FAR});
    out.self_origins.push_back(origin);
    out.facing.push_back(glm::dot(face, g) >= 0.0f ? 1.0f : -1.0f);
    out.triangles.push_back(h.triangle);
  }
  return out;
}

}  // namespace gfield
