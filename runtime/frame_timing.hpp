#pragma once
// Frame times as a benchmark should take them: warm-up frames until two consecutive frames agree
// (shader compilation, uploads and caches settled), then each timed frame measured apart, by the
// wall clock (glFinish) and by the GPU (two GL_TIMESTAMP queries around the frame's commands,
// which unlike GL_TIME_ELAPSED may enclose passes that time themselves), summarised by median
// and range so that a noisy measurement shows as one.

#include <functional>
#include <vector>

#include "runtime/method.hpp"

namespace gfield {

/// The warm-up rule: frames until two consecutive wall times differ by at most this share of
/// the later one, and at least kMinWarmupFrames, at most kMaxWarmupFrames.
inline constexpr double kWarmupAgreement = 0.10;
inline constexpr int kMinWarmupFrames = 3;
inline constexpr int kMaxWarmupFrames = 20;
/// A summary whose range exceeds this share of its median is flagged.
inline constexpr double kMaxSpread = 0.10;

/// Median and range of a set of times, milliseconds.
struct TimeSummary {
  double median = 0.0, min = 0.0, max = 0.0;
  /// (max - min) / median; 0 for no time.
  double spread() const { return median > 0.0 ? (max - min) / median : 0.0; }
  bool noisy() const { return spread() > kMaxSpread; }
};

/// The summary of `ms` (empty: all zero).
TimeSummary summarize(std::vector<double> ms);

struct FrameTimes {
  int warmup_frames = 0;        ///< frames drawn before the timed ones
  std::vector<double> wall_ms;  ///< per timed frame: glFinish to glFinish
  std::vector<double> gpu_ms;   ///< per timed frame: between its GL_TIMESTAMP queries
  FrameStats stats;             ///< the timed frames' parts and counts, summed
};

/// Draws warm-up frames by `frame` under the warm-up rule, then `timed` frames, each timed
/// apart; `frame` draws one frame and adds its parts and counts to the stats it is given.
FrameTimes time_frames(const std::function<void(FrameStats*)>& frame, int timed);

}  // namespace gfield
