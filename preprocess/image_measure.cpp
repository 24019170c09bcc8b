#include "preprocess/image_measure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "gfield/box.hpp"
#include "gfield/limits.hpp"
#include "preprocess/surface_distance.hpp"

namespace gfield {
namespace {

/// Area-weighted percentile (p in [0,1]) of values.
double weighted_percentile(std::vector<std::pair<double, double>> value_weight, double p) {
  if (value_weight.empty())
    return 0.0;
  std::sort(value_weight.begin(), value_weight.end());
  double total = 0.0;
  for (const auto& vw : value_weight)
    total += vw.second;
  double cumulative = 0.0;
  for (const auto& [value, weight] : value_weight) {
    cumulative += weight;
    if (cumulative >= p * total)
      return value;
  }
  return value_weight.back().first;
}

ErrorStats error_stats(std::vector<double> distances, double diagonal) {
  ErrorStats stats;
  stats.samples = distances.size();
  if (distances.empty() || !(diagonal > 0.0))
    return stats;
  std::sort(distances.begin(), distances.end());
  const double scale = 100.0 / diagonal;
  double sum = 0.0;
  for (double d : distances)
    sum += d;
  stats.mean = sum / double(distances.size()) * scale;
  const auto percentile = [&](double p) {
    const size_t k = size_t(std::ceil(p * double(distances.size()))) - 1;
    return distances[std::min(k, distances.size() - 1)] * scale;
  };
  stats.p98 = percentile(0.98);
  stats.p99 = percentile(0.99);
  stats.max = distances.back() * scale;
  return stats;
}

/// Conformal distortion (ratio of the map's singular values) of face f of the map surface ->
/// image uv, and its surface and uv areas; the ratio is -1 for a degenerate surface face.
double face_distortion(const ParameterizedMesh& parameterized, size_t f, double& surface_area,
                       double& uv_area) {
  const TriangleMesh& pm = parameterized.mesh;
  const glm::ivec3& t = pm.triangles[f];
  const glm::dvec3 e1 = pm.positions[t[1]] - pm.positions[t[0]];
  const glm::dvec3 e2 = pm.positions[t[2]] - pm.positions[t[0]];
  const glm::dvec2 u0 = parameterized.corner_uv[3 * f], u1 = parameterized.corner_uv[3 * f + 1],
                   u2 = parameterized.corner_uv[3 * f + 2];
  surface_area = 0.5 * glm::length(glm::cross(e1, e2));
  uv_area = 0.5 * std::abs((u1.x - u0.x) * (u2.y - u0.y) - (u1.y - u0.y) * (u2.x - u0.x));
  const double l1 = glm::length(e1);
  if (!(surface_area > 0.0) || !(l1 > 0.0))
    return -1.0;
  // Local frame of the surface triangle; J maps it onto the uv triangle.
  const glm::dvec2 q1(l1, 0.0), q2(glm::dot(e2, e1) / l1, 2.0 * surface_area / l1);
  const glm::dmat2 surface_edges(q1, q2), uv_edges(u1 - u0, u2 - u0);
  const glm::dmat2 j = uv_edges * glm::inverse(surface_edges);
  // Singular values of a 2x2 matrix.
  const double a = j[0][0], b = j[1][0], c = j[0][1], d = j[1][1];
  const double s1 = std::hypot(a + d, c - b) / 2.0, s2 = std::hypot(a - d, c + b) / 2.0;
  const double sigma1 = s1 + s2, sigma2 = std::abs(s1 - s2);
  return sigma2 > 0.0 ? sigma1 / sigma2 : 1e30;
}

/// Area-weighted conformal distortion and area-ratio percentiles of the map into `report`.
void measure_distortion(const ParameterizedMesh& parameterized, GeometryImageReport& report) {
  const size_t faces = parameterized.mesh.triangles.size();
  std::vector<double> surface_area(faces), uv_area(faces), sigma_ratio(faces);
  double surface_total = 0.0, uv_total = 0.0;
  for (size_t f = 0; f < faces; ++f) {
    sigma_ratio[f] = face_distortion(parameterized, f, surface_area[f], uv_area[f]);
    surface_total += surface_area[f];
    uv_total += uv_area[f];
  }
  // Degenerate uv faces (counted apart) are left out of the conformal distortion.
  std::vector<std::pair<double, double>> conformal, area_ratio;
  for (size_t f = 0; f < faces; ++f) {
    if (sigma_ratio[f] >= 1.0 && uv_area[f] > 1e-12 * uv_total)
      conformal.push_back({sigma_ratio[f], surface_area[f]});
    if (surface_area[f] > 0.0 && uv_total > 0.0)
      area_ratio.push_back(
          {(uv_area[f] / uv_total) / (surface_area[f] / surface_total), surface_area[f]});
  }
  double weighted = 0.0, weight = 0.0;
  for (const auto& [value, w] : conformal) {
    weighted += value * w;
    weight += w;
  }
  report.conformal_mean = weight > 0.0 ? weighted / weight : 0.0;
  report.conformal_p95 = weighted_percentile(conformal, 0.95);
  report.area_p5 = weighted_percentile(area_ratio, 0.05);
  report.area_p50 = weighted_percentile(area_ratio, 0.50);
  report.area_p95 = weighted_percentile(area_ratio, 0.95);
}

}  // namespace

TriangleMesh geometry_image_surface(const GeometryImage& image) {
  TriangleMesh surface;
  const int n = image.size;
  surface.positions.resize(image.position.size());
  for (size_t t = 0; t < image.position.size(); ++t)
    surface.positions[t] = image.position[t];
  auto covered = [&](int i, int j) { return image.coverage[texel_index(image, i, j)] > 0.0f; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if (!covered(i, j) || !covered(i + 1, j) || !covered(i, j + 1) || !covered(i + 1, j + 1))
        continue;
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      surface.triangles.push_back({a, b, d});
      surface.triangles.push_back({a, d, c});
    }
  return surface;
}

double bounds_diagonal(const TriangleMesh& mesh) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

void measure_mesh_to_image(const TriangleMesh& input, const GeometryImage& image,
                           const GeometryImageOptions& options, GeometryImageReport& report) {
  if (!options.measure && options.size != kAutoImageSize)
    return;
  report.mesh_to_image =
      error_stats(distances_to_surface(sample_surface(input, options.error_samples, options.seed),
                                       geometry_image_surface(image)),
                  report.diagonal);
  const double box_diagonal = double(diagonal(image.box));
  if (box_diagonal > 0.0)
    report.ray_offset =
        std::clamp(report.mesh_to_image.p98 / 100.0 * report.diagonal / box_diagonal,
                   double(kMinRayOffset), double(kMaxRayOffset));
}

void measure_image_to_mesh(const TriangleMesh& input, const GeometryImage& image,
                           const ParameterizedMesh& parameterized,
                           const GeometryImageOptions& options, GeometryImageReport& report) {
  measure_distortion(parameterized, report);
  report.image_to_mesh = error_stats(
      distances_to_surface(
          sample_surface(geometry_image_surface(image), options.error_samples, options.seed + 1),
          input),
      report.diagonal);
}

}  // namespace gfield
