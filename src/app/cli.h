#pragma once
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace glint {

// A subcommand defined above app/ (viewer/'s `view`), which app/ does not include: the program's
// main (src/main.cpp) hands it to run_cli. `add` declares it on the parser, its options bound to
// state the command keeps; `run` runs it once the command line named it.
struct CliCommand {
  std::string name;
  std::function<void(CLI::App&)> add;
  std::function<int()> run;
};

// Runs the glint command line: app/'s subcommands, then `more`. Returns the process exit code: 0 on
// success, 1 on a glint::Error (printed as one line "glint: error: ..."), 2 on bad flags (CLI11's
// message).
int run_cli(int argc, char** argv, const std::vector<CliCommand>& more = {});

}  // namespace glint
