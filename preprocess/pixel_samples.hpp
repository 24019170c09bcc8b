#pragma once
// Where the reference tracer's camera samples lie in a pixel: a stratified grid, each sample at
// its stratum's centre or jittered inside it by a hash of the seed, the pixel and the sample (a
// pure function of those: the same picture on any number of threads).

#include <cstdint>

#include <glm/glm.hpp>

namespace gfield {

/// The strata grid nx x ny = `samples_per_pixel`, nx the largest divisor <= its square root.
glm::ivec2 pixel_strata(int samples_per_pixel);

/// Image-plane position (pixels, y down) of sample `s` of pixel (x, y) of an image `width`
/// pixels wide with strata `grid`: the stratum's centre, or with `jitter` a point in it drawn
/// from `seed`.
glm::dvec2 pixel_sample(int x, int y, int s, int width, glm::ivec2 grid, bool jitter,
                        std::uint64_t seed);

}  // namespace gfield
