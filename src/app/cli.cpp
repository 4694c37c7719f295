#include "app/cli.h"

#include "app/accel_bench_command.h"
#include "app/bench_command.h"
#include "app/compare_command.h"
#include "app/devices_command.h"
#include "app/info_command.h"
#include "app/render_command.h"
#include "app/time_limit.h"
#include "core/error.h"
#include "core/interruption.h"
#include "core/log.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>

namespace glint {
namespace {

// The command as typed, for run records; arguments with spaces are quoted.
std::string command_line_text(int argc, char** argv) {
  std::string text;
  for (int i = 0; i < argc; ++i) {
    const std::string argument = argv[i];
    if (i > 0) text += ' ';
    if (argument.find(' ') != std::string::npos) {
      text += '"';
      text += argument;
      text += '"';
    } else {
      text += argument;
    }
  }
  return text;
}

}  // namespace

int run_cli(int argc, char** argv, const std::vector<CliCommand>& more) {
  CLI::App app{"glint: hybrid screen-space + ray-traced reflections for walkthroughs of static and deformable scenes",
               "glint"};
  app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION);
  app.require_subcommand(1);
  bool verbose = false;
  app.add_flag("-v,--verbose", verbose, "Print progress and diagnostic details to stderr");

  InfoOptions info;
  add_info_command(app, info);
  DevicesOptions devices;
  add_devices_command(app, devices);
  RenderOptions render;
  add_render_command(app, render);
  CompareOptions compare;
  add_compare_command(app, compare);
  AccelBenchOptions accel_bench;
  add_accel_bench_command(app, accel_bench);
  BenchOptions bench;
  add_bench_command(app, bench);
  for (const CliCommand& command : more) command.add(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints CLI11's one-line reason and a pointer to --help
    return 2;
  }
  if (verbose) set_log_level(LogLevel::info);

  try {
    if (app.got_subcommand("info")) return run_info_command(info);
    if (app.got_subcommand("devices")) return run_devices_command(devices);
    if (app.got_subcommand("render")) {
      render.command_line = command_line_text(argc, argv);
      return run_render_command(render);
    }
    if (app.got_subcommand("compare")) return run_compare_command(compare);
    if (app.got_subcommand("accel-bench")) return run_accel_bench_command(accel_bench);
    if (app.got_subcommand("bench")) {
      bench.command_line = command_line_text(argc, argv);
      return run_bench_command(bench);
    }
    for (const CliCommand& command : more)
      if (app.got_subcommand(command.name)) return command.run();
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return interrupted_exit_code();
  } catch (const TimeLimitReached& e) {
    std::fprintf(stderr, "glint: %s\n", e.what());
    return kTimeLimitExitCode;
  } catch (const Error& e) {
    std::fprintf(stderr, "glint: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "glint: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace glint
