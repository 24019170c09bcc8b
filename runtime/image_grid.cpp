#include "runtime/image_grid.hpp"

#include <glm/gtx/norm.hpp>

namespace gfield {

std::vector<unsigned> geometry_image_triangles(const GeometryImage& image) {
  const int n = image.size;
  std::vector<unsigned> indices;
  const auto covered = [&](int i, int j) {
    return image.coverage[texel_index(image, i, j)] > 0.5f;
  };
  for (int j = 0; j + 1 < n; ++j) {
    for (int i = 0; i + 1 < n; ++i) {
      if (!covered(i, j) || !covered(i + 1, j) || !covered(i, j + 1) || !covered(i + 1, j + 1))
        continue;
      const unsigned a = unsigned(texel_index(image, i, j));
      const unsigned b = unsigned(texel_index(image, i + 1, j));
      const unsigned c = unsigned(texel_index(image, i, j + 1));
      const unsigned d = unsigned(texel_index(image, i + 1, j + 1));
      const float ad = glm::distance2(image.position[a], image.position[d]);
      const float bc = glm::distance2(image.position[b], image.position[c]);
      if (ad <= bc) {
        indices.insert(indices.end(), {a, b, d, a, d, c});
      } else {
        indices.insert(indices.end(), {a, b, c, b, d, c});
      }
    }
  }
  return indices;
}

}  // namespace gfield
