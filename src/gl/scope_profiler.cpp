#include "gl/scope_profiler.h"

#include "core/error.h"

#include <algorithm>
#include <utility>

namespace glint {
namespace {

// Thread-local, as GlPassScope's name: a GL context and the passes using it belong to one thread.
thread_local ScopeProfiler* t_active = nullptr;

double now_ms() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

ScopeProfiler::ScopeProfiler(PassTimingMethod method) : method_(method) {
  if (method_ == PassTimingMethod::finish_wall_clock) return;
  GLint bits = 0;
  glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
  if (bits <= 0) fail("ScopeProfiler: this OpenGL implementation has no GL_TIMESTAMP counter (0 bits)");
}

ScopeProfiler::~ScopeProfiler() {
  if (t_active == this) t_active = nullptr;
}

ScopeProfiler* ScopeProfiler::active() { return t_active; }

void ScopeProfiler::begin_frame() {
  if (in_frame_) fail("ScopeProfiler::begin_frame: frame {} was not ended", next_frame_);
  if (t_active != nullptr && t_active != this)
    fail("ScopeProfiler::begin_frame: another profiler is active on this thread");
  QuerySet& set = current();
  // Last used kFramesInFlight frames ago; normally taken long since.
  if (set.pending) taken_early_.push_back(read(set));
  set.frame = next_frame_;
  set.scopes.clear();
  open_.clear();
  in_frame_ = true;
  t_active = this;
}

void ScopeProfiler::end_frame() {
  if (!in_frame_) fail("ScopeProfiler::end_frame without begin_frame");
  QuerySet& set = current();
  if (!open_.empty())
    fail("ScopeProfiler::end_frame inside scope '{}'", set.scopes[static_cast<std::size_t>(open_.back())].name);
  set.pending = true;
  in_frame_ = false;
  t_active = nullptr;
  ++next_frame_;
}

void ScopeProfiler::begin_scope(std::string_view name) {
  if (!in_frame_) fail("ScopeProfiler: scope '{}' begun outside begin_frame()/end_frame()", name);
  QuerySet& set = current();
  Scope scope{std::string(name), open_.empty() ? -1 : open_.back(), static_cast<int>(open_.size()), 0.0, 0.0};
  open_.push_back(static_cast<int>(set.scopes.size()));
  if (method_ == PassTimingMethod::finish_wall_clock) {
    glFinish();  // the work before the scope does not count towards it
    scope.begin_ms = now_ms();
    set.scopes.push_back(std::move(scope));
    return;
  }
  set.scopes.push_back(std::move(scope));
  while (set.queries.size() < 2 * set.scopes.size()) set.queries.push_back(create_query(GL_TIMESTAMP));
  glQueryCounter(set.queries[2 * (set.scopes.size() - 1)].id(), GL_TIMESTAMP);
}

void ScopeProfiler::end_scope() noexcept {
  if (!in_frame_ || open_.empty()) return;
  QuerySet& set = current();
  const auto index = static_cast<std::size_t>(open_.back());
  open_.pop_back();
  if (method_ == PassTimingMethod::finish_wall_clock) {
    glFinish();
    set.scopes[index].milliseconds = now_ms() - set.scopes[index].begin_ms;
    return;
  }
  glQueryCounter(set.queries[2 * index + 1].id(), GL_TIMESTAMP);
}

bool ScopeProfiler::available(const QuerySet& set) const {
  if (method_ == PassTimingMethod::finish_wall_clock) return true;
  // Each query is asked: availability of one says nothing about another in the GL specification.
  for (std::size_t i = 0; i < 2 * set.scopes.size(); ++i) {
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(set.queries[i].id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    if (ready != GL_TRUE) return false;
  }
  return true;
}

FrameScopes ScopeProfiler::read(QuerySet& set) {
  FrameScopes frame{set.frame, {}};
  frame.scopes.reserve(set.scopes.size());
  for (std::size_t i = 0; i < set.scopes.size(); ++i) {
    const Scope& scope = set.scopes[i];
    double milliseconds = scope.milliseconds;
    if (method_ == PassTimingMethod::gpu_queries) {
      GLuint64 begin_ns = 0, end_ns = 0;
      glGetQueryObjectui64v(set.queries[2 * i].id(), GL_QUERY_RESULT, &begin_ns);  // waits only if not there
      glGetQueryObjectui64v(set.queries[2 * i + 1].id(), GL_QUERY_RESULT, &end_ns);
      milliseconds = static_cast<double>(static_cast<std::int64_t>(end_ns - begin_ns)) * 1e-6;
    }
    // Parents come before their children, so the parent's path is already there.
    std::string path = scope.parent < 0 ? scope.name
                                        : frame.scopes[static_cast<std::size_t>(scope.parent)].path + "/" + scope.name;
    frame.scopes.push_back({scope.name, std::move(path), scope.depth, scope.parent, milliseconds});
  }
  set.pending = false;
  return frame;
}

std::optional<FrameScopes> ScopeProfiler::take_frame(std::uint64_t frame, bool wait) {
  if (frame >= next_frame_) fail("ScopeProfiler::take_frame: frame {} has not ended", frame);
  const auto early = std::find_if(taken_early_.begin(), taken_early_.end(),
                                  [&](const FrameScopes& scopes) { return scopes.frame == frame; });
  if (early != taken_early_.end()) {
    FrameScopes scopes = std::move(*early);
    taken_early_.erase(early);
    return scopes;
  }
  QuerySet& set = sets_[frame % kFramesInFlight];
  if (!set.pending || set.frame != frame) fail("ScopeProfiler::take_frame: frame {} was already taken", frame);
  if (!wait && !available(set)) return std::nullopt;
  return read(set);
}

}  // namespace glint
