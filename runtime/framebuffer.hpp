#pragma once
// The frame a method renders into: RGBA32F colour (linear radiance), an RGBA32F hit attachment
// (the geometry-field method's per-pixel counts) and 24-bit depth, with their readback.

#include <vector>

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gfield/image.hpp"
#include "runtime/render_target.hpp"

namespace gfield {

/// Linear RGBA pixels, row 0 at the TOP of the picture, index y * width + x.
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<glm::vec4> pixels;
};

class Framebuffer {
 public:
  /// (Re)allocates for `width` x `height`; false if the FBO is incomplete.
  bool resize(int width, int height);
  /// Binds for drawing and sets the viewport.
  void bind() const { target_.bind(); }
  /// Reads the colour attachment back (waits for the GPU), flipped so row 0 is the top.
  RgbaImage read() const;
  /// The colour's rgb as an Image (linear radiance, rows top to bottom).
  Image read_image() const;
  /// Reads the hit attachment back (same layout as read()).
  std::vector<glm::vec4> read_hits() const;

  int width() const { return target_.width(); }
  int height() const { return target_.height(); }
  GLuint framebuffer() const { return target_.framebuffer(); }
  GLuint color_texture() const { return target_.texture(0); }
  GLuint hits_texture() const { return target_.texture(1); }

 private:
  RenderTarget target_;
};

}  // namespace gfield
