#include "runtime/framebuffer.hpp"

namespace gfield {

Framebuffer::~Framebuffer() {
  release();
}

void Framebuffer::release() {
  if (framebuffer_ != 0)
    glDeleteFramebuffers(1, &framebuffer_);
  if (color_ != 0)
    glDeleteTextures(1, &color_);
  if (hits_ != 0)
    glDeleteTextures(1, &hits_);
  if (depth_ != 0)
    glDeleteRenderbuffers(1, &depth_);
  framebuffer_ = color_ = hits_ = depth_ = 0;
}

bool Framebuffer::resize(int width, int height) {
  if (width == width_ && height == height_ && framebuffer_ != 0)
    return true;
  release();
  width_ = width;
  height_ = height;
  glCreateTextures(GL_TEXTURE_2D, 1, &color_);
  glTextureStorage2D(color_, 1, GL_RGBA32F, width, height);
  glCreateTextures(GL_TEXTURE_2D, 1, &hits_);
  glTextureStorage2D(hits_, 1, GL_RGBA32F, width, height);
  glCreateRenderbuffers(1, &depth_);
  glNamedRenderbufferStorage(depth_, GL_DEPTH_COMPONENT24, width, height);
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, color_, 0);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT1, hits_, 0);
  glNamedFramebufferRenderbuffer(framebuffer_, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(framebuffer_, 2, buffers);
  return glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
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
  return {width_, height_, read_flipped(color_, width_, height_)};
}

std::vector<glm::vec4> Framebuffer::read_hits() const {
  return read_flipped(hits_, width_, height_);
}

}  // namespace gfield
