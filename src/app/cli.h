#pragma once

namespace glint {

// Runs the glint command line. Returns the process exit code: 0 on success, 1 on a glint::Error
// (printed as one line "glint: error: ..."), 2 on bad flags (CLI11's message).
int run_cli(int argc, char** argv);

}  // namespace glint
