#pragma once
// Stratified supersampling shared by the renderers: sub-pixel offsets, the clip-space shift that
// applies one to a projection, and the average of one frame per sample.

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "gfield/image.hpp"
#include "runtime/framebuffer.hpp"

namespace gfield {

/// Offset of sample `sample` of `spp` from the pixel centre, in pixels (x right, y down), in
/// (-0.5, 0.5)^2: the centre of its cell of an nx x ny = spp grid, nx the largest divisor of spp
/// <= sqrt(spp) (the reference tracer's strata).
inline glm::vec2 stratified_pixel_offset(int sample, int spp) {
  spp = std::max(1, spp);
  int nx = std::max(1, int(std::sqrt(double(spp))));
  while (spp % nx != 0)
    --nx;
  const int ny = spp / nx;
  return {(float(sample % nx) + 0.5f) / float(nx) - 0.5f,
          (float(sample / nx) + 0.5f) / float(ny) - 0.5f};
}

/// `projection` moved so that the fragment at pixel centre p of a width x height target shows what
/// lies along the camera ray through p + jitter (pixels, x right, y down): the ray the shaders
/// compute for their sample (`pixel + u_jitter`) and the reference tracer's sample position.
inline glm::mat4 jittered_projection(const glm::mat4& projection, glm::vec2 jitter, int width,
                                     int height) {
  // A point at p + jitter must land on p: shift the picture by -jitter (NDC y points up).
  return glm::translate(glm::mat4(1.0f), glm::vec3(-2.0f * jitter.x / float(width),
                                                   2.0f * jitter.y / float(height), 0.0f)) *
         projection;
}

/// The average of `spp` frames of width x height, frame s drawn by render_frame(target, offset)
/// with offset = stratified_pixel_offset(s, spp).
template <typename RenderFrame>
Image render_supersampled(int width, int height, int spp, RenderFrame&& render_frame) {
  Framebuffer target;
  target.resize(width, height);
  spp = std::max(1, spp);
  Image image(width, height);
  for (int s = 0; s < spp; ++s) {
    render_frame(target, stratified_pixel_offset(s, spp));
    const RgbaImage frame = target.read();
    for (size_t i = 0; i < image.pixels.size(); ++i)
      image.pixels[i] += glm::vec3(frame.pixels[i]) / float(spp);
  }
  return image;
}

}  // namespace gfield
