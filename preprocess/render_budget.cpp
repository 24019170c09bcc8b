#include "preprocess/render_budget.hpp"

#include <cstdio>

#include <glm/glm.hpp>

namespace gfield {

RenderBudget estimate_render(int width, int height, int samples_per_pixel) {
  RenderBudget b;
  b.image_bytes = double(width) * double(height) * double(sizeof(glm::vec3));
  b.camera_samples = double(width) * double(height) * double(samples_per_pixel);
  b.estimated_seconds = b.camera_samples * 3.0 / kEstimatedRaysPerSecond;
  return b;
}

namespace {

std::string human_seconds(double s) {
  char buffer[64];
  if (s < 120.0) {
    std::snprintf(buffer, sizeof(buffer), "%.0f s", s);
  } else if (s < 7200.0) {
    std::snprintf(buffer, sizeof(buffer), "%.0f min", s / 60.0);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%.1f h", s / 3600.0);
  }
  return buffer;
}

}  // namespace

bool check_render_budget(int width, int height, int samples_per_pixel, std::string& error) {
  const RenderBudget budget = estimate_render(width, height, samples_per_pixel);
  if (budget.image_bytes <= kMaxImageBytes && budget.camera_samples <= kMaxCameraSamples &&
      width <= 65536 && height <= 65536) {
    return true;
  }
  char message[512];
  std::snprintf(message, sizeof(message),
                "refusing %dx%d at %d spp: %.3g camera samples (limit %.3g), image %.2f GB "
                "(limit %.1f GB), estimated %s on this machine",
                width, height, samples_per_pixel, budget.camera_samples, kMaxCameraSamples,
                budget.image_bytes / 1e9, kMaxImageBytes / 1e9,
                human_seconds(budget.estimated_seconds).c_str());
  error = message;
  return false;
}

}  // namespace gfield
