// The reference ray tracer (see reference_tracer.hpp and docs/reference-tracer.md).

#include "preprocess/reference_tracer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>

#include "geometry/mesh_appearance.hpp"
#include "gfield/environment.hpp"
#include "gfield/gpu_contract.hpp"
#include "gfield/optics.hpp"
#include "gfield/stopwatch.hpp"
#include "preprocess/pixel_samples.hpp"
#include "preprocess/tracer_scene.hpp"

namespace gfield {
namespace {

struct Counters {
  std::uint64_t secondary = 0;
  std::uint64_t shadow = 0;
};

}  // namespace

struct ReferenceTracer::Impl : TracerScene {
  /// The albedo at a diffuse hit: the material's texture, or its colour times the mesh's own
  /// base colour there (exact: the mesh's texture looked up at the hit's uv).
  glm::dvec3 albedo_at(const SurfaceHit& hit) const {
    const SceneObject& object = objects[size_t(hit.object)].object;
    glm::dvec3 albedo(texture_albedo(object.material, glm::vec2(hit.uv)));
    if (object.material.texture == TextureType::kMesh && hit.face >= 0) {
      const MeshRecord& m = meshes[size_t(object.shape.mesh)];
      albedo *= glm::dvec3(base_color_at(m.mesh, m.appearance, size_t(hit.face), hit.weights));
    }
    return albedo;
  }

  glm::dvec3 shade_diffuse(const SurfaceHit& hit, glm::dvec3 incoming, Counters& counters) const {
    const glm::dvec3 albedo = albedo_at(hit);
    // Two-sided: the normal facing the viewer.
    const double facing = glm::dot(incoming, hit.geometric_normal) < 0.0 ? 1.0 : -1.0;
    const glm::dvec3 n = facing * hit.shading_normal;
    glm::dvec3 light_sum(scene.ambient);
    for (const Light& light : scene.lights) {
      glm::dvec3 l;
      double distance;
      if (light.type == LightType::kDirectional) {
        l = -glm::dvec3(light.direction);
        distance = std::numeric_limits<double>::infinity();
      } else {
        l = glm::dvec3(light.position) - hit.position;
        distance = glm::length(l);
        if (distance <= 0.0)
          continue;
        l /= distance;
      }
      const double cosine = glm::dot(n, l);
      if (cosine <= 0.0 || glm::dot(l, facing * hit.geometric_normal) <= 0.0)
        continue;
      ++counters.shadow;
      SurfaceHit blocker;
      const TracerRay shadow = spawn(hit, l);
      if (intersect(shadow, std::isinf(distance) ? 1e30 : distance, kOpaqueMask, blocker)) {
        continue;
      }
      const double falloff = std::isinf(distance) ? 1.0 : 1.0 / (distance * distance);
      light_sum += glm::dvec3(light.color) * double(light.intensity) * cosine * falloff;
    }
    return albedo * light_sum;
  }

  glm::dvec3 radiance(const TracerRay& ray, int depth, double weight, const RenderOptions& options,
                      Counters& counters) const {
    SurfaceHit hit;
    if (!intersect(ray, std::numeric_limits<double>::infinity(), kAllMask, hit)) {
      return glm::dvec3(environment_radiance(environment, glm::vec3(ray.direction)));
    }
    const Material& material = objects[size_t(hit.object)].object.material;
    const glm::dvec3 d = ray.direction;
    const bool front = glm::dot(d, hit.geometric_normal) < 0.0;
    const glm::dvec3 n = front ? hit.shading_normal : -hit.shading_normal;
    switch (material.type) {
      case MaterialType::kDiffuse:
        return shade_diffuse(hit, d, counters);
      case MaterialType::kMirror: {
        if (depth >= options.max_depth)
          return glm::dvec3(0.0);
        glm::dvec3 r = glm::normalize(reflect(d, n));
        if (glm::dot(r, front ? hit.geometric_normal : -hit.geometric_normal) <= 0.0) {
          // An interpolated normal can send the reflection into the surface: use the face's.
          const glm::dvec3 g = front ? hit.geometric_normal : -hit.geometric_normal;
          r = glm::normalize(reflect(d, g));
        }
        ++counters.secondary;
        const glm::dvec3 tint(material.color);
        return tint * radiance(spawn(hit, r), depth + 1, weight, options, counters);
      }
      case MaterialType::kDielectric: {
        // Outside every dielectric is air (index 1); the segment just travelled was inside the
        // object when we hit its surface from the back.
        glm::dvec3 attenuation(1.0);
        if (!front)
          attenuation = glm::exp(-glm::dvec3(material.absorption) * hit.t);
        if (depth >= options.max_depth)
          return glm::dvec3(0.0);
        const double n1 = front ? 1.0 : material.ior;
        const double n2 = front ? material.ior : 1.0;
        const InterfaceSplit split = split_at_interface(d, n, n1, n2, options.dielectric);
        glm::dvec3 sum(0.0);
        const bool prune = options.dielectric == DielectricMode::kFull;
        if (split.reflected_weight > 0.0 &&
            (!prune || weight * split.reflected_weight >= options.min_weight)) {
          ++counters.secondary;
          sum +=
              split.reflected_weight * radiance(spawn(hit, split.reflected), depth + 1,
                                                weight * split.reflected_weight, options, counters);
        }
        if (split.transmitted_weight > 0.0 &&
            (!prune || weight * split.transmitted_weight >= options.min_weight)) {
          ++counters.secondary;
          sum += split.transmitted_weight * radiance(spawn(hit, split.transmitted), depth + 1,
                                                     weight * split.transmitted_weight, options,
                                                     counters);
        }
        return attenuation * sum;
      }
    }
    return glm::dvec3(0.0);
  }
};

ReferenceTracer::ReferenceTracer() = default;
ReferenceTracer::~ReferenceTracer() = default;

bool ReferenceTracer::build(const Scene& scene, std::string& error) {
  auto impl = std::make_unique<Impl>();
  if (!impl->build(scene, error))
    return false;
  impl_ = std::move(impl);
  return true;
}

const Scene& ReferenceTracer::scene() const {
  return impl_->scene;
}

glm::dvec3 ReferenceTracer::trace(const TracerRay& ray, const RenderOptions& options) const {
  Counters counters;
  return impl_->radiance(ray, 0, 1.0, options, counters);
}

std::vector<PathEvent> ReferenceTracer::follow_path(const TracerRay& start, int max_events) const {
  std::vector<PathEvent> events;
  TracerRay ray = start;
  for (int k = 0; k < max_events; ++k) {
    SurfaceHit hit;
    if (!impl_->intersect(ray, std::numeric_limits<double>::infinity(), kAllMask, hit)) {
      events.push_back({PathEvent::kEscape, -1, ray.origin, ray.direction});
      return events;
    }
    const Material& material = impl_->objects[size_t(hit.object)].object.material;
    const bool front = glm::dot(ray.direction, hit.geometric_normal) < 0.0;
    const glm::dvec3 n = front ? hit.shading_normal : -hit.shading_normal;
    PathEvent e;
    e.object = hit.object;
    e.position = hit.position;
    if (material.type == MaterialType::kDiffuse) {
      e.kind = PathEvent::kDiffuse;
      e.direction = ray.direction;
      events.push_back(e);
      return events;
    }
    if (material.type == MaterialType::kMirror) {
      e.kind = PathEvent::kMirror;
      e.direction = glm::normalize(reflect(ray.direction, n));
    } else {
      const double n1 = front ? 1.0 : material.ior, n2 = front ? material.ior : 1.0;
      const InterfaceSplit s =
          split_at_interface(ray.direction, n, n1, n2, DielectricMode::kTirOnly);
      e.kind = s.total_internal_reflection ? PathEvent::kTotalInternalReflection
               : front                     ? PathEvent::kEnter
                                           : PathEvent::kExit;
      e.direction = s.total_internal_reflection ? s.reflected : s.transmitted;
    }
    events.push_back(e);
    ray = Impl::spawn(hit, e.direction);
  }
  return events;
}

namespace {

class Progress {
 public:
  Progress(bool enabled, int total) : enabled_(enabled), total_(total) {}
  /// One more row done; returns the rows done.
  int step() {
    const int done = ++done_;
    if (!enabled_)
      return done;
    const int percent = done * 100 / total_;
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || percent == shown_)
      return done;
    shown_ = percent;
    const int bar = percent * 40 / 100;
    std::fprintf(stderr, "\rrender [%.*s%*s] %3d%%", bar,
                 "########################################", 40 - bar, "", percent);
    if (done == total_)
      std::fprintf(stderr, "\n");
    std::fflush(stderr);
    return done;
  }

 private:
  bool enabled_;
  int total_;
  std::atomic<int> done_{0};
  std::mutex mutex_;
  int shown_ = -1;
};

}  // namespace

Image ReferenceTracer::render(const RenderOptions& options, RenderStats* stats) const {
  const Scene& scene = impl_->scene;
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  const int spp = std::max(1, options.samples_per_pixel);
  const glm::ivec2 grid = pixel_strata(spp);
  Image image(width, height);
  std::atomic<std::uint64_t> secondary{0}, shadow{0};
  Progress progress(options.progress, height);
  Stopwatch watch;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height, 1), [&](const tbb::blocked_range<int>& rows) {
        Counters counters;
        for (int y = rows.begin(); y < rows.end() && !stop_requested(options.control); ++y) {
          for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int s = 0; s < spp; ++s) {
              const CameraRay c =
                  camera_ray(scene.camera, width, height,
                             pixel_sample(x, y, s, width, grid, options.jitter, options.seed));
              sum += impl_->radiance({c.origin, c.direction}, 0, 1.0, options, counters);
            }
            image.at(x, y) = glm::vec3(sum / double(spp));
          }
          report_progress(options.control, "render", double(progress.step()) / double(height));
        }
        secondary += counters.secondary;
        shadow += counters.shadow;
      });
  if (stats) {
    stats->seconds = watch.seconds();
    stats->camera_rays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(spp);
    stats->secondary_rays = secondary;
    stats->shadow_rays = shadow;
  }
  return image;
}

RenderStats ReferenceTracer::cast_camera_rays(const RenderOptions& options) const {
  const Scene& scene = impl_->scene;
  const int width = options.width > 0 ? options.width : scene.width;
  const int height = options.height > 0 ? options.height : scene.height;
  const int spp = std::max(1, options.samples_per_pixel);
  const glm::ivec2 grid = pixel_strata(spp);
  std::atomic<std::uint64_t> hits{0};
  Stopwatch watch;
  tbb::parallel_for(
      tbb::blocked_range<int>(0, height, 1), [&](const tbb::blocked_range<int>& rows) {
        std::uint64_t local = 0;
        for (int y = rows.begin(); y < rows.end(); ++y) {
          for (int x = 0; x < width; ++x) {
            for (int s = 0; s < spp; ++s) {
              const CameraRay c =
                  camera_ray(scene.camera, width, height,
                             pixel_sample(x, y, s, width, grid, options.jitter, options.seed));
              SurfaceHit hit;
              local += impl_->intersect({c.origin, c.direction},
                                        std::numeric_limits<double>::infinity(), kAllMask, hit);
            }
          }
        }
        hits += local;
      });
  RenderStats stats;
  stats.seconds = watch.seconds();
  stats.camera_rays = std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(spp);
  return stats;
}

}  // namespace gfield
