#pragma once
// An offscreen render target (RGBA32F colour + 24-bit depth) and its readback.

#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

namespace gfield {

/// Linear RGBA pixels, row 0 at the TOP of the picture, index y * width + x.
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;
};

class Framebuffer {
 public:
  Framebuffer() = default;
  ~Framebuffer();
  Framebuffer(const Framebuffer&) = delete;
  Framebuffer& operator=(const Framebuffer&) = delete;

  /// (Re)allocates for `width` x `height`; false if the FBO is incomplete.
  bool resize(int width, int height);
  /// Binds for drawing and sets the viewport.
  void bind() const;
  /// Reads the colour attachment back (waits for the GPU), flipped so row 0 is the top.
  RgbaImage read() const;
  /// Reads the RG32F hit attachment back (same layout as read()); see `hit_texture()`.
  std::vector<glm::vec4> read_hits() const;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint framebuffer() const { return framebuffer_; }
  GLuint color_texture() const { return color_; }

 private:
  void release();
  GLuint framebuffer_ = 0;
  GLuint color_ = 0;
  GLuint hits_ = 0;
  GLuint depth_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace gfield
