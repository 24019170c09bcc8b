#pragma once
// What the geometry-field method's benchmarks share (bench_runtime_field,
// bench_runtime_complexity): one configuration's timed render with its PSNR against a reference
// picture and its work counted on the GPU, the GPU bytes of each way of meeting the meshes, and the
// work as one line.

#include <cstdio>
#include <string>

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
  double cpu_ms = 0.0;    ///< CPU time per frame (warm-up frames included), all threads
  double psnr = 0.0;
  FrameStats per_sample;  ///< one untimed counting frame
};

/// With --pass auto: draws frames until its trial has chosen the pass at size^2, so that the
/// timed frames are all of that pass.
inline void settle_pass_trial(GeometryFieldMethod& method, const Camera& camera, int size) {
  render_image(method, camera, size, size, 1);
  while (!method.pass_settled())
    render_image(method, camera, size, size, 1);
}

inline Run run(GeometryFieldMethod& method, const Scene& scene, int size, int frames,
               const Image& reference) {
  Run r;
  settle_pass_trial(method, scene.camera, size);
  Image image;
  const double cpu_start = process_cpu_ms();
  const FrameTimes times = time_frames(
      [&](FrameStats* stats) { image = render_image(method, scene.camera, size, size, 1, stats); },
      frames);
  r.cpu_ms = (process_cpu_ms() - cpu_start) / double(times.warmup_frames + frames);
  r.wall = summarize(times.wall_ms);
  r.gpu = summarize(times.gpu_ms);
  r.ms = r.wall.median;
  r.gpu_ms = r.gpu.median;
  r.psnr = compare_images(clamped_to_display(image), reference).psnr;
  method.settings().count_work = true;
  render_image(method, scene.camera, size, size, 1, &r.per_sample);
  method.settings().count_work = false;
  return r;
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
