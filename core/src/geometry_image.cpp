#include "gfield/geometry_image.hpp"

#include <algorithm>
#include <cmath>

namespace gfield {

namespace {

// GL_LINEAR + GL_CLAMP_TO_EDGE: texel centres at (i + 0.5) / n.
template <typename T>
T bilinear(const std::vector<T>& texels, int n, glm::vec2 uv) {
  const glm::vec2 p = uv * float(n) - 0.5f;
  const glm::vec2 f = glm::floor(p);
  const glm::vec2 w = p - f;
  const int i0 = std::clamp(int(f.x), 0, n - 1);
  const int j0 = std::clamp(int(f.y), 0, n - 1);
  const int i1 = std::clamp(int(f.x) + 1, 0, n - 1);
  const int j1 = std::clamp(int(f.y) + 1, 0, n - 1);
  const auto at = [&](int i, int j) { return texels[size_t(j) * size_t(n) + size_t(i)]; };
  return (at(i0, j0) * (1.0f - w.x) + at(i1, j0) * w.x) * (1.0f - w.y) +
         (at(i0, j1) * (1.0f - w.x) + at(i1, j1) * w.x) * w.y;
}

}  // namespace

glm::vec3 sample_position(const GeometryImage& image, glm::vec2 uv) {
  return bilinear(image.position, image.size, uv);
}

glm::vec3 sample_normal(const GeometryImage& image, glm::vec2 uv) {
  const glm::vec3 n = bilinear(image.normal, image.size, uv);
  const float len = glm::length(n);
  return len > 0.0f ? n / len : n;
}

glm::vec3 sample_albedo(const GeometryImage& image, glm::vec2 uv) {
  return image.albedo.empty() ? glm::vec3(1.0f) : bilinear(image.albedo, image.size, uv);
}

}  // namespace gfield
