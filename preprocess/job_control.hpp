#pragma once
// Progress of a long job (an asset build, a reference render) and a way to stop it from another
// thread. The Python module runs gfield.build and gfield.render on a thread of their own and
// watches them through this (a progress callback, Ctrl-C: python/src/interruptible.hpp); the CLI
// passes none.

#include <atomic>
#include <functional>

namespace gfield {

/// The error of a job stopped through JobControl::stop.
inline constexpr const char* kInterrupted = "interrupted";

struct JobControl {
  /// Called with the stage ("mesh", "image", "field", "write", "verify", "render") and the share
  /// of it done, in [0, 1]. Called from the job's worker threads too: thread-safe and quick.
  std::function<void(const char* stage, double done)> report;
  /// Set from any thread: the job stops at its next check (between stages; per table row or tile
  /// of the field's casts; per picture row of a render) and fails with kInterrupted.
  const std::atomic<bool>* stop = nullptr;
};

/// True when `control` is given and asks the job to stop.
inline bool stop_requested(const JobControl* control) {
  return control != nullptr && control->stop != nullptr &&
         control->stop->load(std::memory_order_relaxed);
}

/// Reports `done` of `stage` to `control`, when it has a report function.
inline void report_progress(const JobControl* control, const char* stage, double done) {
  if (control != nullptr && control->report) {
    control->report(stage, done);
  }
}

}  // namespace gfield
