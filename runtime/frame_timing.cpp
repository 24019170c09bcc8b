#include "runtime/frame_timing.hpp"

#include <algorithm>
#include <cmath>

#include "runtime/pass_clock.hpp"

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
  glFinish();  // the frame's clocks start on an idle GPU
  PassClock clock(true);
  frame(stats);
  wall_ms = clock.read();
  gpu_ms = clock.gpu_ms(0);
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
