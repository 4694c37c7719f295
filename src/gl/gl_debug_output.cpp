#include "gl/gl_debug_output.h"

#include "core/log.h"
#include "gl/gl_pass_scope.h"

#include <epoxy/gl.h>
#include <fmt/format.h>

#include <string_view>
#include <utility>

namespace glint {
namespace {

struct PendingError {
  std::string first;  // formatted first error
  int more = 0;       // errors after the first, before anyone looked
};
thread_local std::optional<PendingError> t_pending;

std::string_view source_name(GLenum source) {
  switch (source) {
    case GL_DEBUG_SOURCE_API: return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM: return "window system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER: return "shader compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY: return "third party";
    case GL_DEBUG_SOURCE_APPLICATION: return "application";
    default: return "other";
  }
}

std::string_view type_name(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR: return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR: return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR: return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY: return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE: return "performance";
    case GL_DEBUG_TYPE_MARKER: return "marker";
    default: return "other";
  }
}

void GLAPIENTRY on_gl_debug_message(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                    const GLchar* message, const void* /*user*/) {
  // Never let an exception (bad_alloc in formatting) escape into the driver.
  try {
    const std::string_view text = length >= 0 ? std::string_view(message, static_cast<std::size_t>(length))
                                              : std::string_view(message);
    if (type == GL_DEBUG_TYPE_ERROR) {
      if (t_pending) {
        ++t_pending->more;
      } else {
        t_pending = PendingError{
            fmt::format("GL error in pass '{}': {} ({} message {})", current_gl_pass(), text, source_name(source), id)};
      }
      return;
    }
    if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM)
      log_warning("GL {} in pass '{}': {}", type_name(type), current_gl_pass(), text);
    else
      log_debug("GL {} ({}) in pass '{}': {}", type_name(type), source_name(source), current_gl_pass(), text);
  } catch (...) {
  }
}

}  // namespace

void install_gl_debug_output() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // callback inside the faulty call, on its thread
  glDebugMessageCallback(on_gl_debug_message, nullptr);
  // Everything on, low severity included: those go to log_debug, which drops them cheaply by default.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::optional<std::string> take_gl_debug_error() {
  if (!t_pending) return std::nullopt;
  std::string message = std::move(t_pending->first);
  if (t_pending->more > 0) message += fmt::format(" (and {} more GL errors)", t_pending->more);
  t_pending.reset();
  return message;
}

}  // namespace glint
