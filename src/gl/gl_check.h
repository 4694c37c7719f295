#pragma once
// check_gl(what): the one place GL errors become glint::Errors. Call it after each pass (and after
// set-up steps). With debug output on, the error recorded by the debug callback is reported (it
// names the pass that issued the faulty call and carries the driver's explanation); otherwise the
// glGetError codes are, with the current pass. Either way all pending error flags are cleared, so
// one fault is reported once.
#include <epoxy/gl.h>

#include <string_view>

namespace glint {

void check_gl(const char* what);

// "GL_INVALID_ENUM", ..., or "0x1234" for a code glint does not know.
std::string gl_error_name(GLenum code);

}  // namespace glint
