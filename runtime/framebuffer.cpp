#include "runtime/framebuffer.hpp"

namespace gfield {

bool Framebuffer::resize(int width, int height) {
  return target_.resize(width, height, {GL_RGBA32F, GL_RGBA32F}, GL_DEPTH_COMPONENT24);
}

namespace {
std::vector<glm::vec4> read_flipped(GLuint texture, int width, int height) {
  std::vector<glm::vec4> raw(size_t(width) * size_t(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, GLsizei(raw.size() * sizeof(glm::vec4)),
                    raw.data());
  std::vector<glm::vec4> flipped(raw.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      flipped[size_t(y) * size_t(width) + size_t(x)] =
          raw[size_t(height - 1 - y) * size_t(width) + size_t(x)];
  return flipped;
}
}  // namespace

RgbaImage Framebuffer::read() const {
  return {width(), height(), read_flipped(target_.texture(0), width(), height())};
}

Image Framebuffer::read_image() const {
  const RgbaImage rgba = read();
  Image image(rgba.width, rgba.height);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = glm::vec3(rgba.pixels[i]);
  return image;
}

std::vector<glm::vec4> Framebuffer::read_hits() const {
  return read_flipped(target_.texture(1), width(), height());
}

}  // namespace gfield
