#include "app/bench/plot_script.h"

#include "app/bench/run_program.h"
#include "core/atomic_file.h"

#include <fmt/format.h>

#include <optional>

namespace glint::bench {
namespace {

// The last non-empty line of a program's output (its error, for a Python traceback).
std::string last_line(const std::string& output) {
  std::size_t end = output.find_last_not_of("\r\n");
  if (end == std::string::npos) return "(no output)";
  const std::size_t start = output.rfind('\n', end);
  return output.substr(start == std::string::npos ? 0 : start + 1, end - (start == std::string::npos ? 0 : start + 1) + 1);
}

}  // namespace

std::string plot_bench_charts(const std::filesystem::path& out) {
  const std::filesystem::path script = out / "plot_bench.py";
  write_file_atomically(script, kPlotBenchScript);
  const std::string by_hand = fmt::format("python3 {} {}", script.string(), out.string());
  // PATH's python3 first; then Debian's, where python3-matplotlib installs, for a PATH whose python3
  // is another installation (pyenv, a virtual environment) without matplotlib.
  std::optional<std::string> python;
  bool any_python = false;
  for (const char* candidate : {"python3", "/usr/bin/python3"}) {
    const std::optional<ProgramResult> check = run_program({candidate, "-c", "import matplotlib"});
    any_python = any_python || check.has_value();
    if (check && check->exit_code == 0) {
      python = candidate;
      break;
    }
  }
  if (!any_python)
    return fmt::format("charts not made: python3 is not on PATH; install python3-matplotlib and run: {}", by_hand);
  if (!python)
    return fmt::format("charts not made: python3 has no matplotlib; install python3-matplotlib and run: {}", by_hand);
  const std::optional<ProgramResult> plot = run_program({*python, script.string(), out.string()});
  if (!plot || plot->exit_code != 0)
    return fmt::format("charts not made: plot_bench.py failed ({}); run it by hand: {}",
                       plot ? last_line(plot->output) : std::string("could not start"), by_hand);
  return "";
}

}  // namespace glint::bench
