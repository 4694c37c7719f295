#pragma once
// GPU time per named pass from GL_TIME_ELAPSED queries, in a ring of kFramesInFlight query sets:
// frame N records into one set while the sets of frames N-1 and N-2 are still in flight, and a
// set's results are read only once GL_QUERY_RESULT_AVAILABLE says they are there (take_completed,
// take_frame), so reading never stalls the pipeline. A set is reused kFramesInFlight frames later;
// only if its results were not read by then does begin_frame() wait for them. Every frame's timings
// come out exactly once, in frame order (a timings.csv row each).
//
// Each frame also gets its latency (begin_frame() to the GPU finishing everything issued before
// end_frame()) and the time it completed, so consecutive frames give the steady-state frame time:
// with queries a GL_TIMESTAMP query at end_frame() against the GPU clock read at begin_frame();
// with wall clock, steady_clock at the end of end_frame()'s glFinish.
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
#include "core/enum_names.h"
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class PassTimingMethod {
  gpu_queries,        // GL_TIME_ELAPSED queries in a ring, no stalls
  finish_wall_clock,  // glFinish() before and after every pass, steady_clock in between
};

// The method that gives real numbers on the renderer named `gl_renderer` (GL_RENDERER):
// finish_wall_clock for Mesa's software rasterisers (llvmpipe, softpipe), gpu_queries otherwise.
PassTimingMethod pass_timing_for_renderer(std::string_view gl_renderer);
inline constexpr EnumNames<PassTimingMethod, 2> kPassTimingNames{
    "pass timing method",
    {{PassTimingMethod::gpu_queries, "gpu_queries"}, {PassTimingMethod::finish_wall_clock, "finish_wall_clock"}}};
// "gpu_queries", "finish_wall_clock" (run.json, summary.json).
inline std::string_view pass_timing_name(PassTimingMethod method) { return kPassTimingNames.name_of(method); }

struct PassTime {
  std::string name;
  double milliseconds = 0.0;
};

struct FrameTimes {
  std::uint64_t frame = 0;  // 0 for the first begin_frame(), then 1, 2, ...
  std::vector<PassTime> passes;  // in the order they ran
  double latency_ms = 0.0;       // begin_frame() to the GPU finishing the frame's work (end_frame())
  double completed_at_ms = 0.0;  // when the GPU finished it, on the timer's own clock (only differences mean anything)
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

  // Frames whose results have arrived since the last call, oldest first (never waits).
  std::vector<FrameTimes> take_completed();
  // Waits for every ended frame's results (end of a run, tests); then take_completed() has them all.
  void wait_for_all();
  // The results of ended frame `frame` (FrameTimes::frame numbering) and of no other: nullopt when
  // they have not arrived and `wait` is false. glint::Error for a frame not ended or already taken.
  std::optional<FrameTimes> take_frame(std::uint64_t frame, bool wait);

private:
  struct QuerySet {
    std::uint64_t frame = 0;
    bool pending = false;       // ended, results not read yet
    std::vector<GlQuery> queries;  // grows to the most passes a frame has used; reused after that
    std::vector<std::string> names;  // names[i] belongs to queries[i]; size = passes this frame
    GlQuery end_stamp;               // GL_TIMESTAMP at end_frame()
    std::int64_t start_ns = 0;       // the GPU clock at begin_frame()
  };

  QuerySet& current() { return sets_[next_frame_ % kFramesInFlight]; }
  bool available(const QuerySet& set) const;
  // Collects the pending sets of frames up to `last_frame`, oldest first, stopping at the first
  // whose results are not there (or waiting for them, when `wait`), so completed_ stays in order.
  void collect_in_order(bool wait, std::uint64_t last_frame = std::numeric_limits<std::uint64_t>::max());
  // Reads `set`'s results into completed_ if they are available or `wait`; returns whether it did.
  bool collect(QuerySet& set, bool wait);

  PassTimingMethod method_;
  std::chrono::steady_clock::time_point pass_start_;  // finish_wall_clock: when the open pass began
  std::chrono::steady_clock::time_point frame_start_;  // finish_wall_clock: begin_frame()
  FrameTimes wall_clock_frame_;                        // finish_wall_clock: the frame being measured
  std::array<QuerySet, kFramesInFlight> sets_;
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
