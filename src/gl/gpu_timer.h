#pragma once
// GPU time per named pass from GL_TIME_ELAPSED queries, double-buffered: frame N records into one
// set of queries while frame N-1's set is read back, so reading a result never waits for the frame
// that issued it. A set is reused two frames later; only if the GPU is still two frames behind does
// begin_frame() wait for it. Every frame's timings come out of take_completed() exactly once, in
// frame order (a timings.csv row each).
//
//   timer.begin_frame();
//   { auto scope = timer.time_pass("ssr"); ssr.run(); }
//   timer.end_frame();
//   for (auto& frame : timer.take_completed()) write_row(frame);
//
// Passes cannot nest: GL allows one GL_TIME_ELAPSED query at a time.
//
// Mesa's llvmpipe answers GL_TIME_ELAPSED with meaningless values (it reports a clock, not the work of
// the pass), so on software renderers the timer measures each pass instead as wall time between two
// glFinish() calls (PassTimingMethod::finish_wall_clock). That serialises CPU and GPU, which is the
// truth for a software renderer anyway; on a real GPU it would hide overlap, so queries stay the default.
#include "gl/gl_objects.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class PassTimingMethod {
  gpu_queries,        // GL_TIME_ELAPSED queries, double-buffered, no stalls
  finish_wall_clock,  // glFinish() before and after every pass, steady_clock in between
};

// The method that gives real numbers on the renderer named `gl_renderer` (GL_RENDERER):
// finish_wall_clock for Mesa's software rasterisers (llvmpipe, softpipe), gpu_queries otherwise.
PassTimingMethod pass_timing_for_renderer(std::string_view gl_renderer);
std::string_view pass_timing_name(PassTimingMethod method);  // "gpu_queries", "finish_wall_clock"

struct PassTime {
  std::string name;
  double milliseconds = 0.0;
};

struct FrameTimes {
  std::uint64_t frame = 0;  // 0 for the first begin_frame(), then 1, 2, ...
  std::vector<PassTime> passes;  // in the order they ran
};

class GpuTimer {
public:
  // Needs a current GL context; with gpu_queries it throws when it cannot time (no timer query bits).
  explicit GpuTimer(PassTimingMethod method = PassTimingMethod::gpu_queries);
  PassTimingMethod method() const { return method_; }

  void begin_frame();
  void end_frame();

  void begin_pass(std::string_view name);
  void end_pass();

  // Ends the pass when it goes out of scope.
  class PassScope {
  public:
    PassScope(GpuTimer& timer, std::string_view name) : timer_(&timer) { timer.begin_pass(name); }
    ~PassScope() {
      if (timer_ != nullptr) timer_->end_pass();
    }
    PassScope(const PassScope&) = delete;
    PassScope& operator=(const PassScope&) = delete;

  private:
    GpuTimer* timer_;
  };
  [[nodiscard]] PassScope time_pass(std::string_view name) { return PassScope(*this, name); }

  // Frames whose results have arrived since the last call, oldest first.
  std::vector<FrameTimes> take_completed();
  // Waits for every ended frame's results (end of a run, tests); then take_completed() has them all.
  void wait_for_all();

private:
  struct QuerySet {
    std::uint64_t frame = 0;
    bool pending = false;       // ended, results not read yet
    std::vector<GlQuery> queries;  // grows to the most passes a frame has used; reused after that
    std::vector<std::string> names;  // names[i] belongs to queries[i]; size = passes this frame
  };

  QuerySet& current() { return sets_[next_frame_ % 2]; }
  // Reads `set`'s results into completed_ if they are available or `wait`; returns whether it did.
  bool collect(QuerySet& set, bool wait);

  PassTimingMethod method_;
  std::chrono::steady_clock::time_point pass_start_;  // finish_wall_clock: when the open pass began
  FrameTimes wall_clock_frame_;                        // finish_wall_clock: the frame being measured
  std::array<QuerySet, 2> sets_;
  std::uint64_t next_frame_ = 0;  // the frame begin_frame() starts next; current one while in a frame
  bool in_frame_ = false;
  bool in_pass_ = false;
  std::vector<FrameTimes> completed_;
};

// Runs `work` as a pass named `name` of `timer`, or untimed when `timer` is null.
template <typename Work>
void run_timed_pass(GpuTimer* timer, std::string_view name, Work&& work) {
  if (timer == nullptr) {
    work();
    return;
  }
  auto scope = timer->time_pass(name);
  work();
}

}  // namespace glint
