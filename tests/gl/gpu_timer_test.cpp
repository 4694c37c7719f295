#include "gl/gl_check.h"
#include "gl/gpu_timer.h"
#include "gl/shader_program.h"
#include "gl_test_context.h"
#include "timed_workload.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>

namespace glint {
namespace {

using GlGpuTimer = testing::GlTest;

using testing::FullScreenWorkload;
using testing::kTimingMethods;

TEST_F(GlGpuTimer, GivesAFiniteNonNegativeTimePerNamedPassAfterADraw) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
  SCOPED_TRACE(std::string(pass_timing_name(method)));
  GpuTimer timer(method);
  timer.begin_frame();
  {
    auto scope = timer.time_pass("fullscreen");
    workload.draw();
  }
  {
    auto scope = timer.time_pass("fullscreen again");
    workload.draw();
  }
  timer.end_frame();
  timer.wait_for_all();
  check_gl("timed frame");

  const auto frames = timer.take_completed();
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].frame, 0u);
  ASSERT_EQ(frames[0].passes.size(), 2u);
  EXPECT_EQ(frames[0].passes[0].name, "fullscreen");
  EXPECT_EQ(frames[0].passes[1].name, "fullscreen again");
  for (const auto& pass : frames[0].passes) {
    EXPECT_TRUE(std::isfinite(pass.milliseconds)) << pass.name;
    EXPECT_GE(pass.milliseconds, 0.0) << pass.name;
  }
  EXPECT_TRUE(timer.take_completed().empty()) << "each frame comes out once";
  }
}

TEST_F(GlGpuTimer, EveryFrameComesOutOnceAndInOrder) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
  SCOPED_TRACE(std::string(pass_timing_name(method)));
  GpuTimer timer(method);
  std::vector<FrameTimes> frames;
  for (int frame = 0; frame < 6; ++frame) {
    timer.begin_frame();
    if (frame != 3) {  // an untimed frame still yields a (empty) row
      auto scope = timer.time_pass("draw");
      workload.draw();
    }
    timer.end_frame();
    for (auto& done : timer.take_completed()) frames.push_back(std::move(done));
    // A ring of kFramesInFlight sets: only that many frames may still be outstanding.
    EXPECT_GE(frames.size() + kFramesInFlight, static_cast<std::size_t>(frame + 1));
    EXPECT_LE(frames.size(), static_cast<std::size_t>(frame + 1));
  }
  timer.wait_for_all();
  for (auto& done : timer.take_completed()) frames.push_back(std::move(done));
  ASSERT_EQ(frames.size(), 6u);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_EQ(frames[i].frame, i);
    EXPECT_EQ(frames[i].passes.size(), i == 3 ? 0u : 1u);
  }
  check_gl("six frames");
  }
}

TEST_F(GlGpuTimer, MisuseIsAnErrorNotAGlError) {
  for (const PassTimingMethod method : kTimingMethods) {
  SCOPED_TRACE(std::string(pass_timing_name(method)));
  GpuTimer timer(method);
  EXPECT_THROW(timer.begin_pass("outside a frame"), Error);
  timer.begin_frame();
  EXPECT_THROW(timer.begin_frame(), Error);
  timer.begin_pass("outer");
  EXPECT_THROW(timer.begin_pass("inner"), Error);  // GL_TIME_ELAPSED queries cannot nest
  EXPECT_THROW(timer.end_frame(), Error);
  timer.end_pass();
  timer.end_frame();
  timer.wait_for_all();
  EXPECT_EQ(timer.take_completed().size(), 1u);
  check_gl("timer misuse");
  }
}

// Wall-clock timing covers everything between the pass's start and end, so a pass that waits 30 ms
// on the CPU measures at least that (a bound on what was done, not a performance claim).
TEST_F(GlGpuTimer, WallClockPassesIncludeTheirWholeDuration) {
  FullScreenWorkload workload;
  GpuTimer timer(PassTimingMethod::finish_wall_clock);
  timer.begin_frame();
  {
    auto scope = timer.time_pass("draw and wait");
    workload.draw();
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  timer.end_frame();
  const auto frames = timer.take_completed();
  ASSERT_EQ(frames.size(), 1u) << "wall-clock frames are complete when they end";
  ASSERT_EQ(frames[0].passes.size(), 1u);
  EXPECT_GE(frames[0].passes[0].milliseconds, 30.0);
}

TEST(GpuTimerMethod, SoftwareRenderersAreTimedWithTheWallClock) {
  EXPECT_EQ(pass_timing_for_renderer("llvmpipe (LLVM 15.0.6, 256 bits)"), PassTimingMethod::finish_wall_clock);
  EXPECT_EQ(pass_timing_for_renderer("softpipe"), PassTimingMethod::finish_wall_clock);
  EXPECT_EQ(pass_timing_for_renderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"), PassTimingMethod::gpu_queries);
}

}  // namespace
}  // namespace glint
