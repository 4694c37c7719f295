#include "gl/gl_pass_scope.h"

#include "gl/scope_profiler.h"

#include <utility>

namespace glint {
namespace {

// Thread-local: GL contexts are current on one thread, and so are the passes that use them.
thread_local std::string t_current_pass;

}  // namespace

GlPassScope::GlPassScope(std::string_view pass_name)
    : previous_(std::exchange(t_current_pass, std::string(pass_name))), profiler_(ScopeProfiler::active()) {
  if (profiler_ != nullptr) profiler_->begin_scope(pass_name);
}

GlPassScope::~GlPassScope() {
  if (profiler_ != nullptr) profiler_->end_scope();
  t_current_pass = std::move(previous_);
}

std::string_view current_gl_pass() {
  return t_current_pass.empty() ? std::string_view("(no pass)") : std::string_view(t_current_pass);
}

}  // namespace glint
