#pragma once
// Runs a helper program (git, python3) to completion and captures what it printed, for `glint
// bench`'s report (the commit) and charts (tools/plot_bench.py). No shell is involved: arguments
// are passed as they are, so paths with spaces or quotes need no escaping.
#include <optional>
#include <string>
#include <vector>

namespace glint::bench {

struct ProgramResult {
  int exit_code = -1;  // -1 when it was killed by a signal
  std::string output;  // stdout and stderr together, in the order they came
};

// `arguments[0]` is looked up on PATH. nullopt when it cannot be started (not installed).
std::optional<ProgramResult> run_program(const std::vector<std::string>& arguments);

}  // namespace glint::bench
