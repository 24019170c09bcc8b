#pragma once
// The reference ray tracer: Whitted-style recursive ray tracing of a scene on Embree (mesh
// instances) plus exact analytic primitives, with exact Fresnel, total internal reflection,
// Beer–Lambert absorption and stratified supersampling. Every rendering method of the project is
// judged against its images (docs/reference-tracer.md).
//
// Deterministic: a pixel's samples depend only on the seed and the pixel, never on threads.

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "gfield/image.hpp"
#include "gfield/scene.hpp"
#include "preprocess/dielectric_split.hpp"
#include "preprocess/job_control.hpp"
#include "preprocess/render_budget.hpp"

namespace gfield {

struct RenderOptions {
  int width = 0;   ///< 0: the scene's
  int height = 0;  ///< 0: the scene's
  int samples_per_pixel = 8;
  /// Reflections/refractions after the camera ray; a path that would need more ends black.
  int max_depth = 10;
  DielectricMode dielectric = DielectricMode::kFull;
  std::uint64_t seed = 1;
  /// Jittered stratified samples; false puts every sample at its stratum's centre (spp = 1:
  /// the pixel centre) for exact comparisons.
  bool jitter = true;
  /// kFull only: branches whose path weight falls below this are not traced.
  double min_weight = 1e-4;
  /// A progress bar on stderr (the CLI enables it when stderr is a terminal).
  bool progress = false;
  /// Progress (stage "render": the share of rows done) and stop: once it asks to stop, the
  /// remaining rows are left black (the caller checks stop_requested). Optional.
  const JobControl* control = nullptr;
};

struct RenderStats {
  double seconds = 0.0;
  std::uint64_t camera_rays = 0;
  std::uint64_t secondary_rays = 0;  ///< reflected and refracted rays
  std::uint64_t shadow_rays = 0;
  std::uint64_t total_rays() const { return camera_rays + secondary_rays + shadow_rays; }
};

/// A world-space ray; `direction` unit.
struct TracerRay {
  glm::dvec3 origin;
  glm::dvec3 direction;
};

/// One step of a followed path (ReferenceTracer::follow_path).
struct PathEvent {
  enum Kind { kEnter, kExit, kTotalInternalReflection, kMirror, kDiffuse, kEscape };
  Kind kind = kEscape;
  int object = -1;            ///< index into Scene::objects (-1 for kEscape)
  glm::dvec3 position{0.0};   ///< world hit point (kEscape: the last ray's origin)
  glm::dvec3 direction{0.0};  ///< unit direction leaving the event (kEscape: the escaping ray's)
};

class ReferenceTracer {
 public:
  ReferenceTracer();
  ~ReferenceTracer();
  ReferenceTracer(const ReferenceTracer&) = delete;
  ReferenceTracer& operator=(const ReferenceTracer&) = delete;

  /// Loads the scene's meshes and environment and builds the Embree scene (one BVH per mesh
  /// file, one instance per object). False with "FILE: problem".
  bool build(const Scene& scene, std::string& error);

  /// Renders width x height (options or scene) linear RGB.
  Image render(const RenderOptions& options, RenderStats* stats = nullptr) const;

  /// Radiance along one ray (depth 0).
  glm::dvec3 trace(const TracerRay& ray, const RenderOptions& options) const;

  /// Follows the path a ray takes when only the refracted ray (or, under total internal
  /// reflection, the reflected one) is continued, and mirrors reflect; stops at a diffuse
  /// surface, on escape, or after `max_events` events.
  std::vector<PathEvent> follow_path(const TracerRay& ray, int max_events) const;

  /// Casts only the camera rays of `options` (first hits, no shading): the raw Embree cost of
  /// the scene, for benchmarks. Fills seconds and camera_rays.
  RenderStats cast_camera_rays(const RenderOptions& options) const;

  const Scene& scene() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gfield
