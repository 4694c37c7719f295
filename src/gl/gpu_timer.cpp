#include "gl/gpu_timer.h"

#include "core/error.h"

#include <algorithm>

namespace glint {

GpuTimer::GpuTimer() {
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
  in_frame_ = true;
}

void GpuTimer::begin_pass(std::string_view name) {
  if (!in_frame_) fail("GpuTimer: pass '{}' begun outside begin_frame()/end_frame()", name);
  if (in_pass_) fail("GpuTimer: pass '{}' begun inside pass '{}'; GL time queries cannot nest", name, current().names.back());
  QuerySet& set = current();
  if (set.names.size() == set.queries.size()) set.queries.push_back(create_query(GL_TIME_ELAPSED));
  glBeginQuery(GL_TIME_ELAPSED, set.queries[set.names.size()].id());
  set.names.emplace_back(name);
  in_pass_ = true;
}

void GpuTimer::end_pass() {
  if (!in_pass_) fail("GpuTimer::end_pass without begin_pass");
  glEndQuery(GL_TIME_ELAPSED);
  in_pass_ = false;
}

void GpuTimer::end_frame() {
  if (!in_frame_) fail("GpuTimer::end_frame without begin_frame");
  if (in_pass_) fail("GpuTimer::end_frame inside pass '{}'", current().names.back());
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
