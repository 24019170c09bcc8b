#pragma once
// `--threads T`: bounds the threads of this process (TBB's pool, which runs Embree's BVH builds,
// the field's casts and verify's rays, and OpenEXR's compression pool).

#include <tbb/global_control.h>

#include <memory>

namespace gfield {

class ThreadLimit {
 public:
  /// At most `threads` threads while this object lives (TBB) and from now on (OpenEXR);
  /// 0: no limit (all cores).
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  std::unique_ptr<tbb::global_control> control_;
};

}  // namespace gfield
