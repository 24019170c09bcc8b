// A frame's or a pass's clock (pass_clock.hpp): untimed it reads 0; timed, its readings grow by
// the wall clock and by the GPU's timestamps, and a clock started inside another reads less.

#include "runtime/pass_clock.hpp"

#include <gtest/gtest.h>

#include "runtime/framebuffer.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {

class PassClockGl : public test::GlSuite {};

void clears(Framebuffer& target, int count) {
  target.bind();
  for (int k = 0; k < count; ++k) {
    glClearColor(float(k % 7) / 7.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
}

TEST_F(PassClockGl, UntimedReadsNothingAndTimedReadingsGrowOnBothClocks) {
  Framebuffer target;
  ASSERT_TRUE(target.resize(256, 256));
  PassClock untimed(false);
  clears(target, 5);
  EXPECT_EQ(untimed.read(), 0.0);
  EXPECT_EQ(untimed.gpu_ms(0), 0.0);
  EXPECT_EQ(untimed.readings(), 0u);

  PassClock frame(true);
  clears(target, 50);
  const double first = frame.read();
  PassClock pass(true);  // nested inside the frame
  clears(target, 50);
  const double pass_ms = pass.read();
  const double second = frame.read();
  EXPECT_EQ(frame.readings(), 2u);
  EXPECT_GT(first, 0.0);
  EXPECT_GT(second, first);
  EXPECT_GT(frame.gpu_ms(0), 0.0);
  EXPECT_GT(frame.gpu_ms(1), frame.gpu_ms(0));
  EXPECT_GT(pass.gpu_ms(0), 0.0);
  EXPECT_LE(pass.gpu_ms(0), frame.gpu_ms(1) - frame.gpu_ms(0) + 1e-3);
  EXPECT_LE(pass_ms, second - first + 1e-3);
  EXPECT_EQ(frame.gpu_ms(2), 0.0);  // not read
}

}  // namespace
}  // namespace gfield
