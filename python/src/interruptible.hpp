#pragma once
// Long C++ jobs (gfield.build, gfield.render) that Ctrl-C stops cleanly and a Python callback
// watches. The job runs on a thread of its own; the calling Python thread waits for it with the
// GIL released, waking every 50 ms to hand the newest progress to the callback and to let
// Python's signal handlers run (PyErr_CheckSignals: a Ctrl-C becomes KeyboardInterrupt there).
// An exception there, from the callback or a handler, asks the job to stop (JobControl::stop),
// waits until it has (its own clean-up ran: a build leaves the old asset as it was) and is then
// raised.

#include <functional>

#include "preprocess/job_control.hpp"
#include "python/src/bindings.hpp"

namespace gfield::python {

/// Runs `job` with a JobControl as described above; `progress` is None or a callable
/// (stage: str, done: float). Returns when the job has returned; an exception the job threw is
/// raised here. Call with the GIL held.
void run_interruptible(const std::function<void(const JobControl&)>& job,
                       const py::object& progress);

}  // namespace gfield::python
