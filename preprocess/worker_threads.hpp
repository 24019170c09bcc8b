#pragma once
// Joining TBB's worker threads before a process exits.

#include <oneapi/tbb/global_control.h>

#include <new>

namespace gfield {

/// Holds TBB's worker threads for its lifetime (the scope of main(), or of a test program's
/// run); at its end they are joined, so that none is still exiting while the process runs its
/// exit handlers: LeakSanitizer's leak check at exit crashed ("Tracer caught signal 11") on a
/// worker thread that exited during it (docs/reliability.md).
class WorkerThreads {
 public:
  WorkerThreads() : handle_(oneapi::tbb::attach{}) {}
  ~WorkerThreads() { oneapi::tbb::finalize(handle_, std::nothrow); }
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;

 private:
  oneapi::tbb::task_scheduler_handle handle_;
};

}  // namespace gfield
