// The procedural textures of the materials: the albedo at a texture coordinate.

#include "gfield/scene.hpp"

#include <algorithm>
#include <cmath>

#include "gfield/image.hpp"

namespace gfield {

glm::vec3 texture_albedo(const Material& material, glm::vec2 uv) {
  switch (material.texture) {
    case TextureType::kNone:
    case TextureType::kMesh:  // the mesh's own base colour multiplies it (mesh_appearance.hpp)
      return material.color;
    case TextureType::kChecker: {
      // The squares' parity in double: a scale of 1e10 (a telephoto view of a checker) takes the
      // square indices beyond int. The products stay float, as the shader's.
      const double cu = std::floor(uv.x * material.checker_scale.x);
      const double cv = std::floor(uv.y * material.checker_scale.y);
      return material.checker_colors[std::fmod(std::fabs(cu + cv), 2.0) == 1.0 ? 1 : 0];
    }
    case TextureType::kColorChart: {
      // ColorChecker Classic, sRGB 8-bit values, rows from the top.
      static const unsigned char kPatches[24][3] = {
          {115, 82, 68},   {194, 150, 130}, {98, 122, 157}, {87, 108, 67},   {133, 128, 177},
          {103, 189, 170}, {214, 126, 44},  {80, 91, 166},  {193, 90, 99},   {94, 60, 108},
          {157, 188, 64},  {224, 163, 46},  {56, 61, 150},  {70, 148, 73},   {175, 54, 60},
          {231, 199, 31},  {187, 86, 149},  {8, 133, 161},  {243, 243, 242}, {200, 200, 200},
          {160, 160, 160}, {122, 122, 121}, {85, 85, 85},   {52, 52, 52}};
      const float u = std::clamp(uv.x, 0.0f, 1.0f) * 6.0f;
      const float v = std::clamp(1.0f - uv.y, 0.0f, 1.0f) * 4.0f;
      const int column = std::min(int(u), 5);
      const int row = std::min(int(v), 3);
      const float fu = u - float(column), fv = v - float(row);
      constexpr float kGap = 0.08f;  // black border around each patch, fraction of a cell
      if (fu < kGap || fu > 1.0f - kGap || fv < kGap || fv > 1.0f - kGap) {
        return glm::vec3(0.01f);
      }
      const unsigned char* c = kPatches[row * 6 + column];
      return glm::vec3(srgb_to_linear(c[0] / 255.0f), srgb_to_linear(c[1] / 255.0f),
                       srgb_to_linear(c[2] / 255.0f));
    }
  }
  return material.color;
}

}  // namespace gfield
