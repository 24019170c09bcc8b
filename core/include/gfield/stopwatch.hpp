#pragma once
// Wall-clock time since a start point (std::chrono::steady_clock), and the process's CPU time:
// the timing helpers of the tools, the runtime and the benchmarks.

#include <chrono>
#include <ctime>

namespace gfield {

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  void restart() { start_ = std::chrono::steady_clock::now(); }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  double milliseconds() const { return 1000.0 * seconds(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

/// CPU time of this process so far, all its threads together (a software GL's rasteriser threads
/// and a tracer's workers included), in ms: what another program's load barely changes.
inline double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace gfield
