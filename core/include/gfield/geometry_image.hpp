#pragma once
// A geometry image: a surface resampled on an n x n grid of its parameter domain [0,1]^2.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/box.hpp"
#include "gfield/check.hpp"
#include "gfield/gpu_contract.hpp"

namespace gfield {

/// Smallest offset of a ray leaving the surface (GeometryImage::ray_offset), in box diagonals:
/// the contract's GF_MIN_RAY_OFFSET.
inline constexpr float kMinRayOffset = gpu::GF_MIN_RAY_OFFSET;
/// Largest ray offset a geometry image may carry, in box diagonals.
inline constexpr float kMaxRayOffset = 0.1f;

/// n x n geometry image. Texel (i, j) = column i, scanline j, stored at index j * n + i, with its
/// centre at uv ((i + 0.5) / n, (j + 0.5) / n).
struct GeometryImage {
  int size = 0;                     ///< n, texels per side
  Box box;                          ///< the box that maps to the unit cube (mesh coordinates)
  std::string source;               ///< mesh file name the image was built from
  std::string build_id;             ///< the build's id (gfield/build_id.hpp); empty: none
  std::vector<glm::vec3> position;  ///< n*n surface points, mesh coordinates
  std::vector<glm::vec3> normal;    ///< n*n unit normals
  std::vector<float> coverage;      ///< n*n: 1 inside the parameterised surface, 0 in padding
  /// n*n linear RGB base colour of the surface (the mesh's texture, vertex colours or material
  /// colours resampled; padding repeats the nearest chart texel); empty when the mesh carries
  /// none.
  std::vector<glm::vec3> albedo;
  /// How far a ray leaving the mesh's surface starts off it (along the surface normal, in box
  /// diagonals) so that a lookup does not find the surface it leaves through the image's
  /// deviation from the mesh: the 98th percentile of the distance from the mesh's surface to the
  /// image's, at least kMinRayOffset (attribute gfield.rayOffset; images without it, or built
  /// unmeasured: kMinRayOffset).
  float ray_offset = kMinRayOffset;
};

/// Texel index of column i, scanline j (both in [0, n)).
inline size_t texel_index(const GeometryImage& image, int i, int j) {
  GF_DCHECK(i >= 0 && i < image.size && j >= 0 && j < image.size, "texel outside the image");
  return size_t(j) * size_t(image.size) + size_t(i);
}

/// Bilinear lookup of the position at uv in [0,1]^2 (texel centres, clamped to the edge), as
/// GL_LINEAR with GL_CLAMP_TO_EDGE would return it.
glm::vec3 sample_position(const GeometryImage& image, glm::vec2 uv);
/// Bilinear lookup of the normal at uv, renormalised.
glm::vec3 sample_normal(const GeometryImage& image, glm::vec2 uv);
/// Bilinear lookup of the albedo at uv; (1, 1, 1) when the image has none.
glm::vec3 sample_albedo(const GeometryImage& image, glm::vec2 uv);

}  // namespace gfield
