#pragma once
// How the OpenGL benchmarks print frame times (runtime/frame_timing.hpp): a summary as median and
// range, flagged when noisy, and the note that says so under each table.

#include <cstdio>
#include <string>

#include "runtime/frame_timing.hpp"

namespace gfield {

/// A summary for a table: "12.3 (12.1-12.6)", with "*" after a noisy one.
inline std::string range_text(const TimeSummary& t) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f (%.1f-%.1f)%s", t.median, t.min, t.max,
                t.noisy() ? "*" : "");
  return text;
}

/// The tables' note on their ms columns.
inline constexpr const char* kFrameTimeNote =
    "ms: the median (and range) of the timed frames' wall times, GPU ms of their GPU times "
    "(GL_TIMESTAMP queries), after warm-up frames until two consecutive ones agree within 10% "
    "(runtime/frame_timing.hpp); *: a range over 10% of its median.";

}  // namespace gfield
