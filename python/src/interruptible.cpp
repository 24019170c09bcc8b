#include "python/src/interruptible.hpp"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

namespace gfield::python {
namespace {

/// What the job's threads tell the waiting Python thread.
struct JobState {
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::exception_ptr failure;
  std::string stage;  ///< the newest progress, not yet handed to the callback when `fresh`
  double done = 0.0;
  bool fresh = false;
};

/// The newest progress, taken out of `state` (under its lock).
struct Snapshot {
  bool finished = false;
  bool fresh = false;
  std::string stage;
  double done = 0.0;
};

/// Waits up to 50 ms for the job to finish (GIL released) and takes the newest progress.
Snapshot wait_a_while(JobState& state) {
  py::gil_scoped_release release;
  std::unique_lock<std::mutex> lock(state.mutex);
  state.finished_signal.wait_for(lock, std::chrono::milliseconds(50),
                                 [&] { return state.finished; });
  Snapshot snapshot{state.finished, state.fresh, state.stage, state.done};
  state.fresh = false;
  return snapshot;
}

}  // namespace

void run_interruptible(const std::function<void(const JobControl&)>& job,
                       const py::object& progress) {
  JobState state;
  std::atomic<bool> stop{false};
  JobControl control;
  control.stop = &stop;
  control.report = [&state](const char* stage, double done) {
    const std::lock_guard<std::mutex> lock(state.mutex);
    state.stage = stage;
    state.done = done;
    state.fresh = true;
  };
  std::thread worker([&] {
    std::exception_ptr failure;
    try {
      job(control);
    } catch (...) {
      failure = std::current_exception();
    }
    const std::lock_guard<std::mutex> lock(state.mutex);
    state.failure = failure;
    state.finished = true;
    state.finished_signal.notify_all();
  });
  const auto join = [&] {
    py::gil_scoped_release release;
    worker.join();
  };
  for (bool finished = false; !finished;) {
    const Snapshot snapshot = wait_a_while(state);
    finished = snapshot.finished;
    try {
      if (snapshot.fresh && !progress.is_none()) {
        progress(snapshot.stage, snapshot.done);
      }
      if (PyErr_CheckSignals() != 0) {
        throw py::error_already_set();
      }
    } catch (...) {
      stop = true;
      join();
      throw;
    }
  }
  join();
  if (state.failure) {
    std::rethrow_exception(state.failure);
  }
}

}  // namespace gfield::python
