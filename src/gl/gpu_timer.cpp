#include "gl/gpu_timer.h"

#include "core/error.h"
#include "gl/gl_renderer.h"
#include "gl/scope_profiler.h"

#include <algorithm>
#include <limits>

namespace glint {

PassTimingMethod pass_timing_for_renderer(std::string_view gl_renderer) {
  return software_gl_renderer(gl_renderer) ? PassTimingMethod::finish_wall_clock : PassTimingMethod::gpu_queries;
}

namespace {

double steady_ms(std::chrono::steady_clock::time_point time) {
  return std::chrono::duration<double, std::milli>(time.time_since_epoch()).count();
}

}  // namespace

GpuTimer::GpuTimer(PassTimingMethod method) : method_(method) {
  if (method_ == PassTimingMethod::finish_wall_clock) return;
  GLint bits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  if (bits <= 0) fail("GpuTimer: this OpenGL implementation has no GL_TIME_ELAPSED counter (0 bits)");
  glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
  if (bits <= 0) fail("GpuTimer: this OpenGL implementation has no GL_TIMESTAMP counter (0 bits)");
}

void GpuTimer::begin_frame() {
  if (in_frame_) fail("GpuTimer::begin_frame: frame {} was not ended", next_frame_);
  QuerySet& set = current();
  // This set was last used kFramesInFlight frames ago; usually its results were read long since.
  if (set.pending) collect_in_order(/*wait=*/true, set.frame);
  set.frame = next_frame_;
  set.names.clear();
  in_frame_ = true;
  if (method_ == PassTimingMethod::finish_wall_clock) {
    wall_clock_frame_ = FrameTimes{next_frame_, {}};
    frame_start_ = std::chrono::steady_clock::now();
    return;
  }
  // The GPU's clock now (commands issued so far need not be done), the base of the frame's latency.
  GLint64 now = 0;
  glGetInteger64v(GL_TIMESTAMP, &now);
  set.start_ns = now;
}

void GpuTimer::begin_pass(std::string_view name) {
  if (!in_frame_) fail("GpuTimer: pass '{}' begun outside begin_frame()/end_frame()", name);
  if (in_pass_) fail("GpuTimer: pass '{}' begun inside pass '{}'; GL time queries cannot nest", name, current().names.back());
  // A pass is also the outermost scope of what it runs, when scopes are profiled.
  if (ScopeProfiler* profiler = ScopeProfiler::active()) profiler->begin_scope(name);
  QuerySet& set = current();
  set.names.emplace_back(name);
  in_pass_ = true;
  if (method_ == PassTimingMethod::finish_wall_clock) {
    glFinish();  // earlier work must not count towards this pass
    pass_start_ = std::chrono::steady_clock::now();
    return;
  }
  if (set.names.size() > set.queries.size()) set.queries.push_back(create_query(GL_TIME_ELAPSED));
  glBeginQuery(GL_TIME_ELAPSED, set.queries[set.names.size() - 1].id());
}

void GpuTimer::end_pass() {
  if (!in_pass_) fail("GpuTimer::end_pass without begin_pass");
  in_pass_ = false;
  if (method_ == PassTimingMethod::finish_wall_clock) {
    glFinish();
    const std::chrono::duration<double, std::milli> elapsed = std::chrono::steady_clock::now() - pass_start_;
    wall_clock_frame_.passes.push_back({current().names.back(), elapsed.count()});
  } else {
    glEndQuery(GL_TIME_ELAPSED);
  }
  if (ScopeProfiler* profiler = ScopeProfiler::active()) profiler->end_scope();
}

void GpuTimer::end_frame() {
  if (!in_frame_) fail("GpuTimer::end_frame without begin_frame");
  if (in_pass_) fail("GpuTimer::end_frame inside pass '{}'", current().names.back());
  if (method_ == PassTimingMethod::finish_wall_clock) {
    glFinish();  // the frame's work after its last pass (readback copies) belongs to its latency
    const auto end = std::chrono::steady_clock::now();
    wall_clock_frame_.latency_ms = std::chrono::duration<double, std::milli>(end - frame_start_).count();
    wall_clock_frame_.completed_at_ms = steady_ms(end);
    completed_.push_back(std::move(wall_clock_frame_));
    in_frame_ = false;
    ++next_frame_;
    return;
  }
  QuerySet& set = current();
  if (!set.end_stamp) set.end_stamp = create_query(GL_TIMESTAMP);
  glQueryCounter(set.end_stamp.id(), GL_TIMESTAMP);  // recorded once everything before it completed
  set.pending = true;
  in_frame_ = false;
  ++next_frame_;
  collect_in_order(/*wait=*/false);  // earlier frames whose results are there; never waits here
}

bool GpuTimer::available(const QuerySet& set) const {
  // The timestamp comes after every pass of the frame, but each query is asked: availability of
  // one query says nothing about another in the GL specification.
  GLuint ready = GL_FALSE;
  glGetQueryObjectuiv(set.end_stamp.id(), GL_QUERY_RESULT_AVAILABLE, &ready);
  if (ready != GL_TRUE) return false;
  for (std::size_t i = 0; i < set.names.size(); ++i) {
    glGetQueryObjectuiv(set.queries[i].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready != GL_TRUE) return false;
  }
  return true;
}

bool GpuTimer::collect(QuerySet& set, bool wait) {
  if (!wait && !available(set)) return false;
  FrameTimes times{set.frame, {}};
  for (std::size_t i = 0; i < set.names.size(); ++i) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(set.queries[i].id(), GL_QUERY_RESULT, &nanoseconds);  // waits only if `wait`
    times.passes.push_back({set.names[i], static_cast<double>(nanoseconds) * 1e-6});
  }
  GLuint64 end_ns = 0;
  glGetQueryObjectui64v(set.end_stamp.id(), GL_QUERY_RESULT, &end_ns);
  times.completed_at_ms = static_cast<double>(end_ns) * 1e-6;
  times.latency_ms = static_cast<double>(static_cast<std::int64_t>(end_ns) - set.start_ns) * 1e-6;
  set.pending = false;
  completed_.push_back(std::move(times));
  return true;
}

void GpuTimer::collect_in_order(bool wait, std::uint64_t last_frame) {
  // Ended sets, oldest first: the frames next_frame_ - kFramesInFlight ... next_frame_ - 1.
  for (std::size_t age = kFramesInFlight; age > 0; --age) {
    if (next_frame_ < age || next_frame_ - age > last_frame) continue;
    QuerySet& set = sets_[(next_frame_ - age) % kFramesInFlight];
    if (!set.pending || set.frame != next_frame_ - age) continue;
    if (!collect(set, wait)) return;
  }
}

std::vector<FrameTimes> GpuTimer::take_completed() {
  if (method_ == PassTimingMethod::gpu_queries) collect_in_order(/*wait=*/false);
  // collect_in_order keeps frame order; sorting keeps that a guarantee, not an accident.
  std::sort(completed_.begin(), completed_.end(),
            [](const FrameTimes& a, const FrameTimes& b) { return a.frame < b.frame; });
  return std::exchange(completed_, {});
}

void GpuTimer::wait_for_all() {
  if (method_ == PassTimingMethod::gpu_queries) collect_in_order(/*wait=*/true);
}

std::optional<FrameTimes> GpuTimer::take_frame(std::uint64_t frame, bool wait) {
  if (frame >= next_frame_) fail("GpuTimer::take_frame: frame {} has not ended", frame);
  const auto find = [&] {
    return std::find_if(completed_.begin(), completed_.end(), [&](const FrameTimes& t) { return t.frame == frame; });
  };
  auto found = find();
  if (found == completed_.end() && method_ == PassTimingMethod::gpu_queries) {
    const QuerySet& set = sets_[frame % kFramesInFlight];
    if (!set.pending || set.frame != frame) fail("GpuTimer::take_frame: frame {} was already taken", frame);
    if (!wait && !available(set)) return std::nullopt;
    collect_in_order(/*wait=*/true, frame);  // the frame and any older ones (complete before it)
    found = find();
  }
  if (found == completed_.end()) fail("GpuTimer::take_frame: frame {} was already taken", frame);
  FrameTimes times = std::move(*found);
  completed_.erase(found);
  return times;
}

}  // namespace glint
