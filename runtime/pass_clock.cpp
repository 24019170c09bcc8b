#include "runtime/pass_clock.hpp"

namespace gfield {

PassClock::PassClock(bool timed) : timed_(timed) {
  if (!timed_)
    return;
  start_.make(GL_TIMESTAMP);
  glQueryCounter(start_.id(), GL_TIMESTAMP);
}

double PassClock::read() {
  if (!timed_)
    return 0.0;
  readings_.emplace_back();
  readings_.back().make(GL_TIMESTAMP);
  glQueryCounter(readings_.back().id(), GL_TIMESTAMP);
  glFinish();
  return clock_.milliseconds();
}

double PassClock::gpu_ms(size_t k) const {
  if (!timed_ || k >= readings_.size())
    return 0.0;
  GLuint64 t0 = 0, t1 = 0;
  glGetQueryObjectui64v(start_.id(), GL_QUERY_RESULT, &t0);
  glGetQueryObjectui64v(readings_[k].id(), GL_QUERY_RESULT, &t1);
  return t1 > t0 ? double(t1 - t0) / 1e6 : 0.0;
}

}  // namespace gfield
