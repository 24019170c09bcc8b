// The checks every mesh reader shares: coordinates in range, indices in range, polygon sizes,
// header counts against the file's size.

#include <cmath>
#include <cstdio>

#include "geometry/mesh_readers.hpp"
#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// `x` rounded to float precision, as every format's coordinates are read. Through a volatile:
/// GCC 12.2 at -O2 and above drops the rounding of a pair of double -> float -> double
/// conversions stored side by side (its SLP vectoriser merges them into one copy).
double float_precision(double x) {
  volatile float rounded = float(x);
  return rounded;
}

}  // namespace

bool add_vertex(MeshSoup& soup, double x, double y, double z, std::string& what) {
  for (const double v : {x, y, z}) {
    if (!std::isfinite(v) || std::abs(v) > kMaxCoordinate) {
      char text[128];
      std::snprintf(text, sizeof(text),
                    std::isfinite(v) ? "vertex coordinate %.6g is beyond the limit of 1e15"
                                     : "vertex coordinate %g: NaN or infinite coordinates are "
                                       "not allowed",
                    v);
      what = text;
      return false;
    }
  }
  if (std::int64_t(soup.mesh.positions.size()) >= kMaxMeshVertices) {
    what = "more than " + std::to_string(kMaxMeshVertices) + " vertices";
    return false;
  }
  soup.mesh.positions.emplace_back(float_precision(x), float_precision(y), float_precision(z));
  return true;
}

bool add_polygon(MeshSoup& soup, std::span<const std::int64_t> corners, std::string& what,
                 const PolygonAttributes& attributes) {
  if (corners.size() < 3) {
    what = "a face with " + std::to_string(corners.size()) + " corners (at least 3)";
    return false;
  }
  if (std::int64_t(corners.size()) > kMaxPolygonCorners) {
    what = "a face with " + std::to_string(corners.size()) + " corners (at most " +
           std::to_string(kMaxPolygonCorners) + ")";
    return false;
  }
  std::vector<glm::ivec3>& triangles = soup.mesh.triangles;
  if (std::int64_t(triangles.size() + corners.size() - 2) > kMaxMeshTriangles) {
    what = "more than " + std::to_string(kMaxMeshTriangles) + " triangles";
    return false;
  }
  ++soup.stats.polygons;
  if (corners.size() > 3) {
    ++soup.stats.triangulated;
  }
  // Attribute arrays start when the first face has the attribute: earlier faces get none. (An
  // array is kept once it is not empty, or from a face that has the attribute: the first face's
  // array is still empty when it starts.)
  const bool uvs = attributes.uvs.size() == corners.size();
  const bool keep_uvs = uvs || !soup.corner_uvs.empty();
  const bool keep_materials = attributes.material >= 0 || !soup.face_material.empty();
  if (uvs && soup.corner_uvs.empty()) {
    soup.corner_uvs.assign(3 * triangles.size(), -1);
  }
  if (attributes.material >= 0 && soup.face_material.empty()) {
    soup.face_material.assign(triangles.size(), -1);
  }
  for (size_t k = 1; k + 1 < corners.size(); ++k) {
    triangles.emplace_back(int(corners[0]), int(corners[k]), int(corners[k + 1]));
    if (keep_uvs) {
      for (const size_t c : {size_t(0), k, k + 1}) {
        soup.corner_uvs.push_back(uvs ? std::int32_t(attributes.uvs[c]) : -1);
      }
    }
    if (keep_materials) {
      soup.face_material.push_back(attributes.material);
    }
  }
  return true;
}

bool add_uv(MeshSoup& soup, double u, double v, std::string& what) {
  for (const double x : {u, v}) {
    if (!std::isfinite(x) || std::abs(x) > kMaxTextureCoordinate) {
      char text[128];
      std::snprintf(text, sizeof(text),
                    "texture coordinate %g is not finite or beyond the limit of 1e4", x);
      what = text;
      return false;
    }
  }
  if (std::int64_t(soup.uvs.size()) >= kMaxMeshVertices) {
    what = "more than " + std::to_string(kMaxMeshVertices) + " texture coordinates";
    return false;
  }
  soup.uvs.emplace_back(float(u), float(v));
  return true;
}

bool set_vertex_color(MeshSoup& soup, glm::dvec3 color, std::string& what) {
  for (int k = 0; k < 3; ++k) {
    if (!(color[k] >= 0.0 && color[k] <= kMaxColorComponent)) {
      char text[128];
      std::snprintf(text, sizeof(text), "vertex colour component %g is not in [0, 1e6]", color[k]);
      what = text;
      return false;
    }
  }
  soup.vertex_color.resize(soup.mesh.positions.size(), glm::vec3(1.0f));
  soup.vertex_color.back() = glm::vec3(color);
  return true;
}

bool check_index(std::int64_t index, std::int64_t vertices, std::string& what) {
  if (index >= 0 && index < vertices) {
    return true;
  }
  what = "vertex index " + std::to_string(index) + " out of range (" + std::to_string(vertices) +
         " vertices)";
  return false;
}

bool check_count(std::int64_t count, std::int64_t limit, std::uint64_t min_bytes,
                 std::uint64_t bytes, std::string_view what_counted, std::string& what) {
  if (count < 0) {
    what = "negative " + std::string(what_counted) + " count " + std::to_string(count);
    return false;
  }
  if (count > limit) {
    what = "header claims " + std::to_string(count) + " " + std::string(what_counted) +
           " (at most " + std::to_string(limit) + ")";
    return false;
  }
  if (min_bytes > 0 && std::uint64_t(count) > bytes / min_bytes) {
    what = "header claims " + std::to_string(count) + " " + std::string(what_counted) +
           ", more than the " + std::to_string(bytes) + " bytes left can hold (truncated file?)";
    return false;
  }
  return true;
}

}  // namespace gfield
