#pragma once
// The work counters of shaders/lib/work.glsl on the GPU (the contract's BUFFER_WORK and WORK_*):
// what a frame's geometry-field lookups and BVH traversals cost, counted by the counting build
// of a program (GF_COUNT_WORK). The counts depend on the rays only, not on the device or its
// load: the regression guard (tests/runtime/work_baselines.json) compares them with committed
// baselines.

#include <array>
#include <cstdint>

#include "gfield/gpu_contract.hpp"
#include "runtime/gl_object.hpp"

namespace gfield {

struct FrameStats;

class WorkCounters {
 public:
  /// Zeroes the counters (making the buffer on first use) and binds them to BUFFER_WORK.
  void clear();
  /// Waits for the GPU and reads the counters.
  std::array<std::uint64_t, gpu::WORK_COUNT> read() const;

 private:
  GlBuffer buffer_;
};

/// The name of counter `kind` in FrameStats ("field lookups", "field texel fetches", ...).
const char* work_count_name(int kind);
/// Adds `counts` to `stats` under work_count_name.
void add_work_counts(FrameStats& stats, const std::array<std::uint64_t, gpu::WORK_COUNT>& counts);

}  // namespace gfield
