#pragma once
// What a reference render of a size would take, and the refusal of one beyond the limits
// (`gfield render`, gfield.render).

#include <string>

namespace gfield {

/// Resources a render would take: refused by the CLI above the limits.
struct RenderBudget {
  double image_bytes = 0.0;        ///< the float image
  double camera_samples = 0.0;     ///< width * height * spp
  double estimated_seconds = 0.0;  ///< at kEstimatedRaysPerSecond, ~3 rays per camera sample
};
/// Camera rays per second assumed for estimates (measured on 2 cores: bench_reference_tracer).
inline constexpr double kEstimatedRaysPerSecond = 4.0e6;
inline constexpr double kMaxCameraSamples = 4.0e9;
inline constexpr double kMaxImageBytes = 2.0e9;
RenderBudget estimate_render(int width, int height, int samples_per_pixel);
/// False with "refusing WxH at S spp: ... camera samples (limit ...), image ... GB (limit ...),
/// estimated ... on this machine" when a render of that size is beyond kMaxCameraSamples,
/// kMaxImageBytes or 65,536 pixels per side (`gfield render` and gfield.render refuse it).
bool check_render_budget(int width, int height, int samples_per_pixel, std::string& error);

}  // namespace gfield
