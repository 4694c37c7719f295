#pragma once
// GPU time of every GlPassScope of a frame, nested to any depth (`glint render --profile-scopes`):
// while a profiler is between begin_frame() and end_frame() on a thread it is that thread's active
// profiler, and every GlPassScope opened there (and every GpuTimer pass, gl/gpu_timer.cpp) records a
// GL_TIMESTAMP query (glQueryCounter) where it begins and where it ends. GpuTimer's GL_TIME_ELAPSED
// queries cannot nest; timestamps can, so a pass's inner scopes get times too:
//
//   gbuffer                          (GpuTimer pass)
//   gbuffer/compute_visibility       (GlPassScope in ComputeVisibilityPass::run)
//   gbuffer/compute_visibility/tiles (GlPassScope around one dispatch)
//
// Query sets form a ring of kFramesInFlight, one per frame in flight, and a frame's results are read
// only once GL_QUERY_RESULT_AVAILABLE says they are there (take_frame), as GpuTimer reads its own:
// nothing stalls the pipeline. A set is reused kFramesInFlight frames later; only if its frame was
// not taken by then does begin_frame() wait for its results.
//
// A timestamp is taken when the GPU has completed every command before it, so a scope's time is from
// the end of the work before it to the end of its own work: the time the scope adds to the frame.
// Work that runs beside GL shows up as GL sees it: a CUDA trace between map and unmap of GL buffers
// (cuda/optix backends) is inside a scope as the wait of the GL commands after the unmap; a CPU
// trace (cpu/embree backends) as the GPU's idle time until the CPU issued the next commands.
// A timestamp between dispatches that could overlap also makes them run one after the other.
//
// With PassTimingMethod::finish_wall_clock (Mesa's llvmpipe, whose timestamps mean nothing; the
// decision is gl/gpu_timer.h's pass_timing_for_renderer) each scope is wall time between glFinish()
// calls instead, so child scopes never add up to more than their parent.
#include "gl/gl_objects.h"
#include "gl/gpu_timer.h"
#include "gl/readback_ring.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct ScopeTime {
  std::string name;        // the scope's own name ("tiles")
  std::string path;        // names from the outermost scope, joined by '/' ("gbuffer/compute_visibility/tiles")
  int depth = 0;           // 0 for a scope opened outside every other
  int parent = -1;         // index of the enclosing scope in FrameScopes::scopes, -1 at depth 0
  double milliseconds = 0.0;
};

struct FrameScopes {
  std::uint64_t frame = 0;         // 0 for the first begin_frame(), then 1, 2, ... (GpuTimer's numbering)
  std::vector<ScopeTime> scopes;   // in the order they began: a parent before its children (tree order)
};

class ScopeProfiler {
public:
  // Needs a current GL context; with gpu_queries it throws when the GL has no GL_TIMESTAMP counter.
  explicit ScopeProfiler(PassTimingMethod method);
  ~ScopeProfiler();  // no longer active on its thread
  ScopeProfiler(const ScopeProfiler&) = delete;
  ScopeProfiler& operator=(const ScopeProfiler&) = delete;

  PassTimingMethod method() const { return method_; }

  // Starts the next frame and makes this the thread's active profiler; end_frame() ends it (every
  // scope must have ended) and deactivates it.
  void begin_frame();
  void end_frame();

  // Called by GlPassScope and GpuTimer on the active profiler. end_scope() never throws (it runs in
  // destructors, also while an exception unwinds); one without an open scope is ignored.
  void begin_scope(std::string_view name);
  void end_scope() noexcept;

  // The scopes of ended frame `frame` (FrameScopes::frame numbering): nullopt when its results have
  // not arrived and `wait` is false. glint::Error for a frame not ended or already taken.
  std::optional<FrameScopes> take_frame(std::uint64_t frame, bool wait);

  // This thread's active profiler, or null: the one check a GlPassScope makes.
  static ScopeProfiler* active();

private:
  struct Scope {
    std::string name;
    int parent = -1;
    int depth = 0;
    double begin_ms = 0.0;  // finish_wall_clock
    double milliseconds = 0.0;
  };
  struct QuerySet {
    std::uint64_t frame = 0;
    bool pending = false;          // ended, not taken yet
    std::vector<Scope> scopes;
    std::vector<GlQuery> queries;  // 2 per scope: begin, end; grows to the most a frame has used
  };

  QuerySet& current() { return sets_[next_frame_ % kFramesInFlight]; }
  bool available(const QuerySet& set) const;
  FrameScopes read(QuerySet& set);  // waits for results that are not there yet

  PassTimingMethod method_;
  std::array<QuerySet, kFramesInFlight> sets_;
  std::vector<FrameScopes> taken_early_;  // read by begin_frame() before take_frame() asked (a wrapped ring)
  std::vector<int> open_;                 // indices of the scopes begun and not ended, innermost last
  std::uint64_t next_frame_ = 0;
  bool in_frame_ = false;
};

}  // namespace glint
