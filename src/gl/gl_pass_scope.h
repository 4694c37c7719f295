#pragma once
// Names the render pass the current thread is issuing GL commands for, so a GL error can say where it
// happened ("GL_INVALID_OPERATION in pass 'ssr'"). Scopes nest; the innermost name wins and the
// outer one comes back when it ends. Costs one string copy per pass.
//
// While a ScopeProfiler (gl/scope_profiler.h) is active on the thread, each scope also records GPU
// timestamps where it begins and ends (`glint render --profile-scopes`); otherwise that costs one
// thread-local pointer check.
#include <string>
#include <string_view>

namespace glint {

class ScopeProfiler;

class GlPassScope {
public:
  explicit GlPassScope(std::string_view pass_name);
  ~GlPassScope();
  GlPassScope(const GlPassScope&) = delete;
  GlPassScope& operator=(const GlPassScope&) = delete;

private:
  std::string previous_;
  ScopeProfiler* profiler_;  // the one active when the scope began, or null
};

// The innermost GlPassScope's name on this thread, or "(no pass)" outside every scope.
std::string_view current_gl_pass();

}  // namespace glint
