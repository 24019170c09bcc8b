#pragma once
// The pass the geometry-field method traces in: a full-screen fragment pass or a compute
// dispatch (shaders/field_trace.frag, field_trace.comp: the same code, the same picture), and
// --pass auto's choice between them, measured on the running device: a GPU that runs fragment
// shaders on part of its chip only (data-centre parts) traces faster in a compute dispatch, a
// CPU renderer may not.

#include <array>
#include <string>
#include <vector>

namespace gfield {

enum class TracePass { kAuto = 0, kCompute = 1, kFragment = 2 };

/// "auto", "compute" or "fragment".
const char* trace_pass_name(TracePass pass);

/// Frames --pass auto times in each pass after the pass's first (its warm-up: compilation and
/// first use), the passes alternating from compute.
inline constexpr int kPassTrialFrames = 2;

/// --pass auto's trial for one shading program at one frame size (`key`); a new key starts it
/// again.
struct PassTrial {
  std::string key;
  /// Per pass (compute, fragment): the tracing GPU ms of each of its frames, warm-up first.
  std::array<std::vector<double>, 2> ms;
};

/// Starts the trial again when `key` is not its own.
void restart_pass_trial(PassTrial& trial, const std::string& key);
/// True once both passes have their timed frames.
bool pass_trial_done(const PassTrial& trial);
/// The pass the next frame traces in: while the trial runs, the one with fewer frames (compute
/// first); then the one whose fastest timed frame is the faster.
TracePass next_trace_pass(const PassTrial& trial);
/// Adds a frame's tracing GPU ms in `pass` (kCompute or kFragment) to the trial: infinity for a
/// pass whose program does not build.
void record_trace_pass(PassTrial& trial, TracePass pass, double gpu_ms);
/// For the panel and --bench: "compute (auto: 41.2 ms against fragment 55.0 ms)", "compute
/// (auto: fragment did not build)", or "compute (auto: measuring)" while the trial runs.
std::string describe_pass_trial(const PassTrial& trial);

}  // namespace gfield
