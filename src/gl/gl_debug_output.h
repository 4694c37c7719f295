#pragma once
// KHR_debug output: the driver calls us synchronously, on the thread and inside the GL call that
// caused the message, so we know the exact pass (current_gl_pass()) that issued the faulty call.
//
// Errors are NOT thrown from the callback: it runs inside the driver's C code, and unwinding through
// it would leave driver locks and state behind. The callback records the first error (with its pass)
// and check_gl() throws it as a glint::Error at the next check. Other messages go to the log:
// high/medium severity as warnings, low/notification as debug.
#include <optional>
#include <string>

namespace glint {

// Enables synchronous debug output with glint's callback on the current context.
void install_gl_debug_output();

// The first GL error reported through debug output on this thread since the last call (formatted,
// naming its pass and the driver's message), and how many more followed; clears it.
std::optional<std::string> take_gl_debug_error();

}  // namespace glint
