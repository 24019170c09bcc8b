#pragma once
// An offscreen render target: colour textures (attachments 0..k-1, nearest filtering) and an
// optional depth renderbuffer, reallocated only when its size or formats change. The G-buffer,
// the image-space screen maps, the glass method's peeled layers and the frame a method renders
// into (runtime/framebuffer.hpp) are render targets.

#include <vector>

#include <epoxy/gl.h>

#include "runtime/gl_object.hpp"

namespace gfield {

class RenderTarget {
 public:
  /// (Re)allocates width x height colour textures of `color_formats` (e.g. GL_RGBA32F) and a
  /// depth renderbuffer of `depth_format` (0: none); keeps them when nothing changed. All colour
  /// attachments are draw buffers. False if the framebuffer is incomplete.
  bool resize(int width, int height, const std::vector<GLenum>& color_formats, GLenum depth_format);
  /// Binds for drawing and sets the viewport.
  void bind() const;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint framebuffer() const { return framebuffer_.id(); }
  /// Colour attachment k's texture.
  GLuint texture(int k) const { return colors_[size_t(k)].id(); }

 private:
  GlFramebuffer framebuffer_;
  std::vector<GlTexture> colors_;
  GlRenderbuffer depth_;
  std::vector<GLenum> color_formats_;
  GLenum depth_format_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace gfield
