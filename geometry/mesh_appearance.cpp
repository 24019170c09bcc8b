#include "geometry/mesh_appearance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "gfield/limits.hpp"

namespace gfield {
namespace {

/// `i` wrapped into [0, n).
int wrap(long long i, int n) {
  const long long r = i % n;
  return int(r < 0 ? r + n : r);
}

/// The material of face `face` (null: none).
const BaseColorMaterial* material_of(const MeshAppearance& a, size_t face) {
  if (a.face_material.empty() || a.face_material[face] < 0) {
    return nullptr;
  }
  return &a.materials[size_t(a.face_material[face])];
}

/// Vertex colours interpolated at `w` (1 without any).
glm::vec3 vertex_color_at(const TriangleMesh& mesh, const MeshAppearance& a, size_t face,
                          glm::dvec3 w) {
  if (a.vertex_color.empty()) {
    return glm::vec3(1.0f);
  }
  const glm::ivec3& t = mesh.triangles[face];
  return glm::vec3(w.x * glm::dvec3(a.vertex_color[size_t(t.x)]) +
                   w.y * glm::dvec3(a.vertex_color[size_t(t.y)]) +
                   w.z * glm::dvec3(a.vertex_color[size_t(t.z)]));
}

}  // namespace

bool carries_base_color(const MeshAppearance& appearance) {
  return !appearance.materials.empty() || !appearance.vertex_color.empty();
}

glm::vec3 texture_lookup(const Image& image, glm::vec2 uv) {
  // Texel centres at (i + 0.5) / width along u and, from the bottom row up, along v.
  const double x = double(uv.x) * image.width - 0.5;
  const double y = (1.0 - double(uv.y)) * image.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const float ax = float(x - fx), ay = float(y - fy);
  const int x0 = wrap((long long)fx, image.width), x1 = wrap((long long)fx + 1, image.width);
  const int y0 = wrap((long long)fy, image.height), y1 = wrap((long long)fy + 1, image.height);
  const glm::vec3 top = glm::mix(image.at(x0, y0), image.at(x1, y0), ax);
  const glm::vec3 bottom = glm::mix(image.at(x0, y1), image.at(x1, y1), ax);
  return glm::mix(top, bottom, ay);
}

glm::vec3 footprint_lookup(const Image& image, glm::vec2 uv, glm::vec2 du, glm::vec2 dv) {
  const glm::vec2 texels(float(image.width), float(image.height));
  const int k = std::clamp(int(std::ceil(glm::length(du * texels))), 1, 32);
  const int l = std::clamp(int(std::ceil(glm::length(dv * texels))), 1, 32);
  glm::vec3 sum(0.0f);
  for (int j = 0; j < l; ++j) {
    for (int i = 0; i < k; ++i) {
      const float s = (float(i) + 0.5f) / float(k) - 0.5f;
      const float t = (float(j) + 0.5f) / float(l) - 0.5f;
      sum += texture_lookup(image, uv + s * du + t * dv);
    }
  }
  return sum / float(k * l);
}

glm::vec2 uv_at(const MeshAppearance& appearance, size_t face, glm::dvec3 w) {
  if (appearance.corner_uv.empty()) {
    return glm::vec2(0.0f);
  }
  const glm::vec2* uv = &appearance.corner_uv[3 * face];
  return glm::vec2(w.x * glm::dvec2(uv[0]) + w.y * glm::dvec2(uv[1]) + w.z * glm::dvec2(uv[2]));
}

glm::vec3 base_color_at(const TriangleMesh& mesh, const MeshAppearance& appearance, size_t face,
                        glm::dvec3 w) {
  glm::vec3 color = vertex_color_at(mesh, appearance, face, w);
  if (const BaseColorMaterial* m = material_of(appearance, face)) {
    color *= m->factor;
    if (m->texture >= 0) {
      color *=
          texture_lookup(appearance.textures[size_t(m->texture)].image, uv_at(appearance, face, w));
    }
  }
  return color;
}

glm::vec3 footprint_color(const TriangleMesh& mesh, const MeshAppearance& appearance, size_t face,
                          glm::dvec3 w, glm::vec2 du, glm::vec2 dv) {
  glm::vec3 color = vertex_color_at(mesh, appearance, face, w);
  if (const BaseColorMaterial* m = material_of(appearance, face)) {
    color *= m->factor;
    if (m->texture >= 0) {
      color *= footprint_lookup(appearance.textures[size_t(m->texture)].image,
                                uv_at(appearance, face, w), du, dv);
    }
  }
  return color;
}

bool check_texture_budget(const std::string& name, int width, int height,
                          const MeshAppearance& appearance, std::string& error) {
  constexpr std::uint64_t kPixelBytes = sizeof(glm::vec3);
  std::uint64_t used = 0;
  for (const MeshTexture& t : appearance.textures)
    used += t.image.pixels.size() * kPixelBytes;
  const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * kPixelBytes;
  if (used + bytes <= kMaxMeshTextureBytes)
    return true;
  char text[256];
  std::snprintf(text, sizeof(text),
                ": %dx%d pixels take %.3g GB decoded (%d bytes a pixel), beyond the texture "
                "budget of %.3g GB (2 GiB for a mesh's textures; %.3g GB taken by its others)",
                width, height, double(bytes) / 1e9, int(kPixelBytes),
                double(kMaxMeshTextureBytes) / 1e9, double(used) / 1e9);
  error = name + text;
  return false;
}

bool load_texture_files(const std::string& mesh, const std::vector<std::string>& files, bool pixels,
                        MeshAppearance& appearance, std::vector<std::string>& warnings,
                        std::string& error) {
  for (const std::string& file : files) {
    MeshTexture texture{file, Image(1, 1, glm::vec3(kMissingTextureGrey))};
    std::error_code ec;
    const bool present = std::filesystem::is_regular_file(file, ec);
    std::string why;
    int width = 0, height = 0;
    if (!present || !std::ifstream(file, std::ios::binary)) {
      warnings.push_back(mesh + ": texture " + file + ": " +
                         (present ? "not readable" : "no such file") + "; mid-grey albedo");
    } else if (!load_image_size(file, width, height, why) ||
               (pixels && (!check_texture_budget(file, width, height, appearance, why) ||
                           !load_image(file, texture.image, why)))) {
      error = mesh + ": texture " + why;
      return false;
    } else if (!pixels) {
      texture.image = Image();
      texture.image.width = width;
      texture.image.height = height;
    }
    appearance.textures.push_back(std::move(texture));
  }
  return true;
}

}  // namespace gfield
