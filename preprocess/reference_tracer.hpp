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
#include "preprocess/job_control.hpp"

namespace gfield {

/// What happens at a dielectric surface.
///  kFull:        reflected and refracted rays, weighted by the exact Fresnel reflectance R and
///                1 - R (1 and 0 under total internal reflection).
///  kRefractOnly: only the refracted ray, weight 1; under total internal reflection the path ends
///                (black).
///  kTirOnly:     the refracted ray with weight 1, or, under total internal reflection only, the
///                reflected ray with weight 1 (the references of Davis & Wyman 2007, Fig. 8).
enum class DielectricMode { kFull, kRefractOnly, kTirOnly };

/// "full", "refract-only", "tir-only" -> mode; false for anything else.
bool parse_dielectric_mode(std::string_view name, DielectricMode& mode);
const char* dielectric_mode_name(DielectricMode mode);

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

/// Reflectance and transmittance at one dielectric interface, as the tracer uses them.
struct InterfaceSplit {
  bool total_internal_reflection = false;
  double reflected_weight = 0.0;
  double transmitted_weight = 0.0;
  glm::dvec3 reflected{0.0};
  glm::dvec3 transmitted{0.0};  ///< zero under total internal reflection
};

/// The split of unit `incident` at a surface with unit normal `normal` facing the incident side,
/// from index n1 into n2, under `mode`.
InterfaceSplit split_at_interface(glm::dvec3 incident, glm::dvec3 normal, double n1, double n2,
                                  DielectricMode mode);

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
