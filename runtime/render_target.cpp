#include "runtime/render_target.hpp"

namespace gfield {

bool RenderTarget::resize(int width, int height, const std::vector<GLenum>& color_formats,
                          GLenum depth_format) {
  if (framebuffer_ && width == width_ && height == height_ && color_formats == color_formats_ &&
      depth_format == depth_format_)
    return true;
  width_ = width;
  height_ = height;
  color_formats_ = color_formats;
  depth_format_ = depth_format;
  framebuffer_.make();
  colors_.clear();
  std::vector<GLenum> buffers;
  for (GLenum format : color_formats) {
    GlTexture& texture = colors_.emplace_back();
    texture.make(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, format, width, height);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    const GLenum attachment = GLenum(GL_COLOR_ATTACHMENT0 + buffers.size());
    glNamedFramebufferTexture(framebuffer_.id(), attachment, texture.id(), 0);
    buffers.push_back(attachment);
  }
  depth_.reset();
  if (depth_format != 0) {
    depth_.make();
    glNamedRenderbufferStorage(depth_.id(), depth_format, width, height);
    glNamedFramebufferRenderbuffer(framebuffer_.id(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                   depth_.id());
  }
  glNamedFramebufferDrawBuffers(framebuffer_.id(), GLsizei(buffers.size()), buffers.data());
  return glCheckNamedFramebufferStatus(framebuffer_.id(), GL_FRAMEBUFFER) ==
         GL_FRAMEBUFFER_COMPLETE;
}

void RenderTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width_, height_);
}

}  // namespace gfield
