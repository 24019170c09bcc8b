#pragma once
// Wall-clock time since a start point (std::chrono::steady_clock): the one timing helper of the
// tools, the runtime and the benchmarks.

#include <chrono>

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

}  // namespace gfield
