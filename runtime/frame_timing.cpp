#include "runtime/frame_timing.hpp"

#include <algorithm>
#include <cmath>

#include "gfield/stopwatch.hpp"
#include "runtime/gl_object.hpp"

namespace gfield {

TimeSummary summarize(std::vector<double> ms) {
  TimeSummary s;
  if (ms.empty())
    return s;
  std::sort(ms.begin(), ms.end());
  const size_t n = ms.size();
  s.median = n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  s.min = ms.front();
  s.max = ms.back();
  return s;
}

namespace {

/// One frame: its wall time (glFinish before and after) and its GPU time (timestamps).
void time_frame(const std::function<void(FrameStats*)>& frame, FrameStats* stats, double& wall_ms,
                double& gpu_ms) {
  GlQuery start, end;
  start.make(GL_TIMESTAMP);
  end.make(GL_TIMESTAMP);
  glFinish();
  const Stopwatch clock;
  glQueryCounter(start.id(), GL_TIMESTAMP);
  frame(stats);
  glQueryCounter(end.id(), GL_TIMESTAMP);
  glFinish();
  wall_ms = clock.milliseconds();
  GLuint64 t0 = 0, t1 = 0;
  glGetQueryObjectui64v(start.id(), GL_QUERY_RESULT, &t0);
  glGetQueryObjectui64v(end.id(), GL_QUERY_RESULT, &t1);
  gpu_ms = t1 > t0 ? double(t1 - t0) / 1e6 : 0.0;
}

}  // namespace

FrameTimes time_frames(const std::function<void(FrameStats*)>& frame, int timed) {
  FrameTimes times;
  double last = -1.0, wall = 0.0, gpu = 0.0;
  for (;;) {
    FrameStats ignored;
    time_frame(frame, &ignored, wall, gpu);
    ++times.warmup_frames;
    const bool agree = last >= 0.0 && std::abs(wall - last) <= kWarmupAgreement * wall;
    if ((agree && times.warmup_frames >= kMinWarmupFrames) ||
        times.warmup_frames >= kMaxWarmupFrames)
      break;
    last = wall;
  }
  for (int f = 0; f < timed; ++f) {
    time_frame(frame, &times.stats, wall, gpu);
    times.wall_ms.push_back(wall);
    times.gpu_ms.push_back(gpu);
  }
  return times;
}

}  // namespace gfield
