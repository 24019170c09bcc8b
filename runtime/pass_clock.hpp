#pragma once
// A frame's or a pass's clock: when timed, the wall milliseconds since it started (glFinish
// before each reading) and, apart, the GPU's, from GL_TIMESTAMP queries taken at its start and
// at each reading (timestamps, unlike GL_TIME_ELAPSED queries, may nest: a pass's clock runs
// inside its frame's). Untimed, it reads 0 and stalls nothing.

#include <cstddef>
#include <vector>

#include "gfield/stopwatch.hpp"
#include "runtime/gl_object.hpp"

namespace gfield {

class PassClock {
 public:
  explicit PassClock(bool timed);
  /// Waits for the GPU and returns the wall ms since the start, taking reading number
  /// readings() (from 0); 0 when untimed.
  double read();
  /// The GPU ms from the start to reading k (waits for its query); 0 when untimed or not read.
  double gpu_ms(size_t k) const;
  size_t readings() const { return readings_.size(); }

 private:
  bool timed_;
  Stopwatch clock_;
  GlQuery start_;
  std::vector<GlQuery> readings_;
};

}  // namespace gfield
