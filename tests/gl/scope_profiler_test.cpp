// ScopeProfiler: GlPassScopes (and GpuTimer passes) record nested times while a profiler's frame is
// open on the thread and nothing otherwise; frames come back once each, also after the ring wrapped.
#include "core/error.h"
#include "gl/gl_pass_scope.h"
#include "gl/gpu_timer.h"
#include "gl/scope_profiler.h"
#include "gl/shader_program.h"
#include "gl_test_context.h"
#include "timed_workload.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace glint {
namespace {

using ScopeProfilerTest = testing::GlTest;

using testing::FullScreenWorkload;
using testing::kTimingMethods;

// outer { draw; inner { draw; deepest { draw } }; second { draw } }
void nested_scopes(FullScreenWorkload& workload) {
  GlPassScope outer("outer");
  workload.draw();
  {
    GlPassScope inner("inner");
    workload.draw();
    GlPassScope deepest("deepest");
    workload.draw();
  }
  GlPassScope second("second");
  workload.draw();
}

std::vector<std::string> paths_of(const FrameScopes& frame) {
  std::vector<std::string> paths;
  for (const ScopeTime& scope : frame.scopes) paths.push_back(scope.path);
  return paths;
}

TEST_F(ScopeProfilerTest, NestedGlPassScopesGetPathsDepthsParentsAndTimes) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
    SCOPED_TRACE(std::string(pass_timing_name(method)));
    ScopeProfiler profiler(method);
    profiler.begin_frame();
    EXPECT_EQ(ScopeProfiler::active(), &profiler);
    nested_scopes(workload);
    profiler.end_frame();
    EXPECT_EQ(ScopeProfiler::active(), nullptr);
    const FrameScopes frame = profiler.take_frame(0, /*wait=*/true).value();
    EXPECT_EQ(frame.frame, 0u);
    ASSERT_EQ(paths_of(frame),
              (std::vector<std::string>{"outer", "outer/inner", "outer/inner/deepest", "outer/second"}));
    const std::vector<int> depths{0, 1, 2, 1}, parents{-1, 0, 1, 0};
    for (std::size_t i = 0; i < frame.scopes.size(); ++i) {
      EXPECT_EQ(frame.scopes[i].depth, depths[i]) << frame.scopes[i].path;
      EXPECT_EQ(frame.scopes[i].parent, parents[i]) << frame.scopes[i].path;
      EXPECT_TRUE(std::isfinite(frame.scopes[i].milliseconds)) << frame.scopes[i].path;
      EXPECT_GE(frame.scopes[i].milliseconds, 0.0) << frame.scopes[i].path;
    }
    EXPECT_EQ(frame.scopes[2].name, "deepest");
    if (method == PassTimingMethod::finish_wall_clock) {
      // Wall clock between glFinish calls: children lie inside their parent's interval, one after another.
      EXPECT_LE(frame.scopes[1].milliseconds + frame.scopes[3].milliseconds, frame.scopes[0].milliseconds);
      EXPECT_LE(frame.scopes[2].milliseconds, frame.scopes[1].milliseconds);
    }
    EXPECT_THROW((void)profiler.take_frame(0, true), Error);  // once only
  }
}

TEST_F(ScopeProfilerTest, ScopesRecordNothingWithoutAnOpenFrame) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
    SCOPED_TRACE(std::string(pass_timing_name(method)));
    EXPECT_EQ(ScopeProfiler::active(), nullptr);
    nested_scopes(workload);  // no profiler at all: nothing to record into, nothing fails
    ScopeProfiler profiler(method);
    nested_scopes(workload);  // a profiler, but between frames
    profiler.begin_frame();
    { GlPassScope only("only"); workload.draw(); }
    profiler.end_frame();
    nested_scopes(workload);  // after the frame
    EXPECT_EQ(paths_of(profiler.take_frame(0, true).value()), std::vector<std::string>{"only"});
    // The GL error names still nest as before, profiler or not.
    {
      GlPassScope outer("outer");
      EXPECT_EQ(current_gl_pass(), "outer");
    }
    EXPECT_EQ(current_gl_pass(), "(no pass)");
  }
}

TEST_F(ScopeProfilerTest, GpuTimerPassesAreTheOutermostScopes) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
    SCOPED_TRACE(std::string(pass_timing_name(method)));
    GpuTimer timer(method);
    ScopeProfiler profiler(method);
    timer.begin_frame();
    profiler.begin_frame();
    {
      auto pass = timer.time_pass("gbuffer");
      GlPassScope scope("compute_visibility");
      { GlPassScope stage("tiles"); workload.draw(); }
    }
    { auto pass = timer.time_pass("light"); workload.draw(); }
    profiler.end_frame();
    timer.end_frame();
    const FrameScopes frame = profiler.take_frame(0, true).value();
    EXPECT_EQ(paths_of(frame), (std::vector<std::string>{"gbuffer", "gbuffer/compute_visibility",
                                                         "gbuffer/compute_visibility/tiles", "light"}));
    const FrameTimes times = timer.take_frame(0, true).value();
    ASSERT_EQ(times.passes.size(), 2u);  // the timer's own numbers are still there
    if (method == PassTimingMethod::finish_wall_clock) {
      EXPECT_LE(times.passes[0].milliseconds, frame.scopes[0].milliseconds);  // the scope encloses the pass
    }
  }
}

TEST_F(ScopeProfilerTest, EveryFrameComesBackOnceAlsoWhenTheRingWrapped) {
  FullScreenWorkload workload;
  for (const PassTimingMethod method : kTimingMethods) {
    SCOPED_TRACE(std::string(pass_timing_name(method)));
    ScopeProfiler profiler(method);
    // Two frames more than the ring holds, none taken meanwhile: begin_frame reads the oldest sets.
    constexpr int kFrames = static_cast<int>(kFramesInFlight) + 2;
    for (int frame = 0; frame < kFrames; ++frame) {
      profiler.begin_frame();
      {
        GlPassScope scope("frame " + std::to_string(frame));
        workload.draw();
      }
      profiler.end_frame();
    }
    EXPECT_THROW((void)profiler.take_frame(kFrames, true), Error);  // not ended
    for (int frame = 0; frame < kFrames; ++frame) {
      const FrameScopes scopes = profiler.take_frame(static_cast<std::uint64_t>(frame), true).value();
      EXPECT_EQ(scopes.frame, static_cast<std::uint64_t>(frame));
      EXPECT_EQ(paths_of(scopes), std::vector<std::string>{"frame " + std::to_string(frame)});
    }
  }
}

TEST_F(ScopeProfilerTest, EndingAFrameInsideAScopeIsAnError) {
  ScopeProfiler profiler(PassTimingMethod::finish_wall_clock);
  profiler.begin_frame();
  {
    GlPassScope open("still open");
    EXPECT_THROW(profiler.end_frame(), Error);
  }
  profiler.end_frame();  // the scope ended: now it can
  EXPECT_EQ(paths_of(profiler.take_frame(0, true).value()), std::vector<std::string>{"still open"});
  profiler.end_scope();  // none open, no frame: ignored (GlPassScope destructors call it)
}

TEST_F(ScopeProfilerTest, ADestroyedProfilerIsNoLongerActive) {
  {
    ScopeProfiler profiler(PassTimingMethod::finish_wall_clock);
    profiler.begin_frame();  // a frame that failed half-way is never ended
    EXPECT_EQ(ScopeProfiler::active(), &profiler);
  }
  EXPECT_EQ(ScopeProfiler::active(), nullptr);
  GlPassScope later("later");  // would touch the destroyed profiler otherwise
}

}  // namespace
}  // namespace glint
