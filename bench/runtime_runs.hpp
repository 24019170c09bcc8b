#pragma once
// What the geometry-field method's benchmarks share (bench_runtime_field,
// bench_runtime_complexity): one configuration's timed render with its PSNR against a reference
// picture and its work counted on the GPU, the GPU bytes of each way of meeting the meshes, and the
// work as one line.

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "gfield/image_metrics.hpp"
#include "gfield/stopwatch.hpp"
#include "runtime/frame_timing.hpp"
#include "runtime/methods/geometry_field.hpp"
#include "time_text.hpp"

namespace gfield {

/// One configuration's timed render: ms per frame, PSNR against the reference, and its work.
struct Run {
  double ms = 0.0;        ///< the timed frames' median wall time (frame_timing.hpp)
  double gpu_ms = 0.0;    ///< their median GPU time
  TimeSummary wall, gpu;  ///< the timed frames' wall and GPU times
  /// The timed frames' tracing pass alone, GPU time: the frame less its G-buffer, the part in
  /// which the routes to the meshes differ (the G-buffer rasterises the same meshes for both).
  TimeSummary tracing;
  double cpu_ms = 0.0;  ///< CPU time per frame (warm-up frames included), all threads
  double psnr = 0.0;
  FrameStats per_sample;  ///< one untimed counting frame
};

/// A configuration's timed frames, gathered over one or more rounds (ms per frame each).
struct TimedFrames {
  std::vector<double> wall_ms, gpu_ms, tracing_ms;
  double cpu_ms = 0.0;  ///< CPU time of all frames drawn, warm-up frames included
  int drawn = 0;        ///< frames drawn, warm-up frames included
  Image image;          ///< the last frame
};

/// With --pass auto: draws frames until its trial has chosen the pass at size^2, so that the
/// timed frames are all of that pass.
inline void settle_pass_trial(GeometryFieldMethod& method, const Camera& camera, int size) {
  render_image(method, camera, size, size, 1);
  while (!method.pass_settled())
    render_image(method, camera, size, size, 1);
}

/// One round of the method's present configuration: warm-up frames (frame_timing.hpp), then
/// `frames` timed frames added to `t`.
inline void time_round(GeometryFieldMethod& method, const Scene& scene, int size, int frames,
                       TimedFrames& t) {
  settle_pass_trial(method, scene.camera, size);
  const double cpu_start = process_cpu_ms();
  std::vector<double> tracing_ms;  // every frame's, the timed ones last
  const FrameTimes times = time_frames(
      [&](FrameStats* stats) {
        const double before = stats->gpu_part_ms("tracing");
        t.image = render_image(method, scene.camera, size, size, 1, stats);
        tracing_ms.push_back(stats->gpu_part_ms("tracing") - before);
      },
      frames);
  t.cpu_ms += process_cpu_ms() - cpu_start;
  t.drawn += times.warmup_frames + frames;
  t.wall_ms.insert(t.wall_ms.end(), times.wall_ms.begin(), times.wall_ms.end());
  t.gpu_ms.insert(t.gpu_ms.end(), times.gpu_ms.begin(), times.gpu_ms.end());
  t.tracing_ms.insert(t.tracing_ms.end(), tracing_ms.end() - frames, tracing_ms.end());
}

/// The run of the method's present configuration from its timed frames: their summaries, the
/// last frame's PSNR against `reference`, and one counting frame's work.
inline Run finish_run(GeometryFieldMethod& method, const Scene& scene, int size,
                      const TimedFrames& t, const Image& reference) {
  Run r;
  r.wall = summarize(t.wall_ms);
  r.gpu = summarize(t.gpu_ms);
  r.tracing = summarize(t.tracing_ms);
  r.ms = r.wall.median;
  r.gpu_ms = r.gpu.median;
  r.cpu_ms = t.cpu_ms / double(std::max(1, t.drawn));
  r.psnr = compare_images(clamped_to_display(t.image), reference).psnr;
  method.settings().count_work = true;
  render_image(method, scene.camera, size, size, 1, &r.per_sample);
  method.settings().count_work = false;
  return r;
}

inline Run run(GeometryFieldMethod& method, const Scene& scene, int size, int frames,
               const Image& reference) {
  TimedFrames t;
  time_round(method, scene, size, frames, t);
  return finish_run(method, scene, size, t, reference);
}

/// Runs `configurations` configurations (`configure(k)` sets the method to configuration k) in
/// `rounds` rounds of `frames` timed frames each, in turn, so that a slow spell of a shared
/// machine falls on every configuration alike; each one's frames pooled.
inline std::vector<Run> run_interleaved(GeometryFieldMethod& method, const Scene& scene, int size,
                                        int frames, int rounds, const Image& reference,
                                        int configurations,
                                        const std::function<void(int)>& configure) {
  std::vector<TimedFrames> timed(static_cast<size_t>(configurations));
  for (int round = 0; round < rounds; ++round)
    for (int k = 0; k < configurations; ++k) {
      configure(k);
      time_round(method, scene, size, frames, timed[size_t(k)]);
    }
  std::vector<Run> runs;
  for (int k = 0; k < configurations; ++k) {
    configure(k);
    runs.push_back(finish_run(method, scene, size, timed[size_t(k)], reference));
  }
  return runs;
}

/// GPU bytes of the meshes' geometry images and fields, and of their BVHs and rasterised meshes.
inline void asset_bytes(const GpuScene& gpu, double& field_mb, double& bvh_mb) {
  field_mb = bvh_mb = 0.0;
  for (const GpuAsset& a : gpu.assets().assets()) {
    const double mesh = double(a.source.vertex_count) * sizeof(GpuVertex) +
                        double(a.source.index_count) * sizeof(unsigned);
    field_mb += double(a.image_bytes + a.field_bytes) / 1e6;
    bvh_mb += (double(a.bvh_bytes) + mesh) / 1e6;
  }
}

inline std::string work_line(const FrameStats& s) {
  const auto count = [&](int kind) { return s.count(work_count_name(kind)); };
  char text[256];
  const double lookups = count(gpu::WORK_LOOKUPS), traversals = count(gpu::WORK_BVH_TRAVERSALS);
  if (lookups > 0.0) {
    std::snprintf(text, sizeof(text), "%.0f lookups: %.1f field + %.1f image fetches, %.1f Newton",
                  lookups, count(gpu::WORK_FIELD_FETCHES) / lookups,
                  count(gpu::WORK_IMAGE_FETCHES) / lookups,
                  count(gpu::WORK_NEWTON_STEPS) / lookups);
  } else if (traversals > 0.0) {
    std::snprintf(text, sizeof(text), "%.0f traversals: %.1f nodes, %.1f triangles", traversals,
                  count(gpu::WORK_BVH_NODES) / traversals,
                  count(gpu::WORK_BVH_TRIANGLES) / traversals);
  } else {
    std::snprintf(text, sizeof(text), "no mesh traced");
  }
  return text;
}

}  // namespace gfield
