#include "gl/gl_check.h"

#include "core/error.h"
#include "gl/gl_debug_output.h"
#include "gl/gl_pass_scope.h"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace glint {

std::string gl_error_name(GLenum code) {
  switch (code) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_CONTEXT_LOST: return "GL_CONTEXT_LOST";
    default: return fmt::format("{:#06x}", code);
  }
}

void check_gl(const char* what) {
  // glGetError returns one flag per call; a lost context may keep returning one, hence the bound.
  std::vector<std::string> codes;
  for (int i = 0; i < 16; ++i) {
    const GLenum code = glGetError();
    if (code == GL_NO_ERROR) break;
    codes.push_back(gl_error_name(code));
  }
  if (auto debug_error = take_gl_debug_error()) {
    if (codes.empty()) fail("{}: {}", what, *debug_error);
    fail("{}: {} [{}]", what, *debug_error, fmt::join(codes, ", "));
  }
  if (!codes.empty()) fail("{}: {} in pass '{}'", what, fmt::join(codes, ", "), current_gl_pass());
}

}  // namespace glint
