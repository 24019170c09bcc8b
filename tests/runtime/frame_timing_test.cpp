// Frame times as the benchmarks take them (frame_timing.hpp): medians and ranges, the warm-up
// rule, a wall and a GPU time for every timed frame, and gfield-view --bench printing both.

#include "runtime/frame_timing.hpp"

#include <gtest/gtest.h>

#include "runtime/framebuffer.hpp"
#include "test_support/build_paths.hpp"
#include "test_support/cli_run.hpp"
#include "test_support/gl_suite.hpp"

namespace gfield {
namespace {

TEST(FrameTiming, SummariesHaveTheMedianAndTheRangeAndFlagASpreadAboveATenth) {
  const TimeSummary odd = summarize({5.0, 1.0, 3.0});
  EXPECT_EQ(odd.median, 3.0);
  EXPECT_EQ(odd.min, 1.0);
  EXPECT_EQ(odd.max, 5.0);
  EXPECT_TRUE(odd.noisy());
  const TimeSummary even = summarize({10.0, 10.4, 10.2, 10.8});
  EXPECT_DOUBLE_EQ(even.median, 10.3);
  EXPECT_NEAR(even.spread(), 0.8 / 10.3, 1e-12);
  EXPECT_FALSE(even.noisy());
  EXPECT_EQ(summarize({}).median, 0.0);
  EXPECT_EQ(summarize({}).spread(), 0.0);
}

class FrameTimingGl : public test::GlSuite {};

TEST_F(FrameTimingGl, WarmUpFramesComeFirstAndEveryTimedFrameHasAWallAndAGpuTime) {
  Framebuffer target;
  ASSERT_TRUE(target.resize(256, 256));
  int frames = 0;
  const FrameTimes t = time_frames(
      [&](FrameStats* stats) {
        ++frames;
        target.bind();
        for (int k = 0; k < 50; ++k) {
          glClearColor(float(k) / 50.0f, 0.0f, 0.0f, 1.0f);
          glClear(GL_COLOR_BUFFER_BIT);
        }
        stats->add_count("clears", 50.0);
      },
      5);
  EXPECT_GE(t.warmup_frames, kMinWarmupFrames);
  EXPECT_LE(t.warmup_frames, kMaxWarmupFrames);
  EXPECT_EQ(frames, t.warmup_frames + 5);
  ASSERT_EQ(t.wall_ms.size(), 5u);
  ASSERT_EQ(t.gpu_ms.size(), 5u);
  for (size_t f = 0; f < 5; ++f) {
    EXPECT_GT(t.wall_ms[f], 0.0);
    EXPECT_GT(t.gpu_ms[f], 0.0);  // the timestamps enclose the clears
  }
  EXPECT_EQ(t.stats.count("clears"), 250.0);  // the timed frames' counts only
}

TEST(FrameTimingView, BenchPrintsWallAndGpuTimesApart) {
  const test::CliRun r = test::run_program(gfield::build_paths::view(),
                                           std::string(gfield::build_paths::data_dir()) +
                                               "/scenes/two-mirror-spheres.json --headless --bench "
                                               "--frames 4 "
                                               "--size 32x32 --method field");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("the median of 3 frame(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wall: median "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("; GPU: median "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warm-up frame(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("GPU per pass: G-buffer "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gfield
