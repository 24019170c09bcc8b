#include "preprocess/thread_limit.hpp"

#include <OpenEXR/ImfThreading.h>

namespace gfield {

ThreadLimit::ThreadLimit(int threads) {
  if (threads > 0) {
    control_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                     size_t(threads));
    Imf::setGlobalThreadCount(threads);
  }
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace gfield
