#include "gl/gpu_timer.h"

#include "core/error.h"

#include <algorithm>

namespace glint {

PassTimingMethod pass_timing_for_renderer(std::string_view gl_renderer) {
  const bool software = gl_renderer.find("llvmpipe") != std::string_view::npos ||
                        gl_renderer.find("softpipe") != std::string_view::npos;
  return software ? PassTimingMethod::finish_wall_clock : PassTimingMethod::gpu_queries;
}

std::string_view pass_timing_name(PassTimingMethod method) {
  return method == PassTimingMethod::gpu_queries ? "gpu_queries" : "finish_wall_clock";
}

GpuTimer::GpuTimer(PassTimingMethod method) : method_(method) {
  if (method_ == PassTimingMethod::finish_wall_clock) return;
  GLint bits = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_QUERY_COUNTER_BITS, &bits);
  if (bits <= 0) fail("GpuTimer: this OpenGL implementation has no GL_TIME_ELAPSED counter (0 bits)");
}

void GpuTimer::begin_frame() {
  if (in_frame_) fail("GpuTimer::begin_frame: frame {} was not ended", next_frame_);
  QuerySet& set = current();
  // This set was last used two frames ago; usually its results are long there.
  if (set.pending) collect(set, /*wait=*/true);
  set.frame = next_frame_;
  set.names.clear();
  wall_clock_frame_ = FrameTimes{next_frame_, {}};
  in_frame_ = true;
}

void GpuTimer::begin_pass(std::string_view name) {
  if (!in_frame_) fail("GpuTimer: pass '{}' begun outside begin_frame()/end_frame()", name);
  if (in_pass_) fail("GpuTimer: pass '{}' begun inside pass '{}'; GL time queries cannot nest", name, current().names.back());
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
    return;
  }
  glEndQuery(GL_TIME_ELAPSED);
}

void GpuTimer::end_frame() {
  if (!in_frame_) fail("GpuTimer::end_frame without begin_frame");
  if (in_pass_) fail("GpuTimer::end_frame inside pass '{}'", current().names.back());
  if (method_ == PassTimingMethod::finish_wall_clock) {
    completed_.push_back(std::move(wall_clock_frame_));
    in_frame_ = false;
    ++next_frame_;
    return;
  }
  current().pending = true;
  in_frame_ = false;
  ++next_frame_;
  // The previous frame's set: take its results if they are there, never wait here.
  QuerySet& previous = current();
  if (previous.pending) collect(previous, /*wait=*/false);
}

bool GpuTimer::collect(QuerySet& set, bool wait) {
  if (!wait) {
    for (std::size_t i = 0; i < set.names.size(); ++i) {
      GLuint available = GL_FALSE;
      glGetQueryObjectuiv(set.queries[i].id(), GL_QUERY_RESULT_AVAILABLE, &available);
      if (available != GL_TRUE) return false;
    }
  }
  FrameTimes times{set.frame, {}};
  for (std::size_t i = 0; i < set.names.size(); ++i) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(set.queries[i].id(), GL_QUERY_RESULT, &nanoseconds);  // waits only if `wait`
    times.passes.push_back({set.names[i], static_cast<double>(nanoseconds) * 1e-6});
  }
  set.pending = false;
  completed_.push_back(std::move(times));
  return true;
}

std::vector<FrameTimes> GpuTimer::take_completed() {
  // Sets alternate, so frames arrive in order; sorting keeps that a guarantee, not an accident.
  std::sort(completed_.begin(), completed_.end(),
            [](const FrameTimes& a, const FrameTimes& b) { return a.frame < b.frame; });
  return std::exchange(completed_, {});
}

void GpuTimer::wait_for_all() {
  // Oldest first: the set of the frame before the last ended one, then the last ended one.
  QuerySet& older = sets_[next_frame_ % 2];
  QuerySet& newer = sets_[(next_frame_ + 1) % 2];
  if (older.pending) collect(older, true);
  if (newer.pending) collect(newer, true);
}

}  // namespace glint
