#pragma once
// `glint view [scene]`: the interactive viewer (src/viewer/, docs/viewer.md): a window with panels
// running the frame loop of `glint render`, live settings, debug views, stats, screenshots, and
// `--script FILE` to drive it without input. viewer/ sits above app/: the program's main
// (src/main.cpp) hands view_cli_command() to app's run_cli, which knows no viewer.
#include "app/cli.h"
#include "app/render_command.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace glint::viewer {

struct ViewOptions {
  ViewOptions() {
    render.width = 960;  // with the panel columns the window fits a 1920 x 1080 screen
    render.height = 540;
  }
  RenderOptions render;              // scene and the starting settings (render's defaults, 960 x 540)
  std::string script;                // --script FILE
  int frame = 0;                     // --frame: the walkthrough frame shown first
  std::vector<std::string> settings;  // --set NAME=VALUE, applied in order
  bool offscreen = false;            // --offscreen: the script without a window (headless EGL)
};

void add_view_command(CLI::App& app, ViewOptions& options);
int run_view_command(const ViewOptions& options);
// The `view` subcommand for run_cli: its options live in the returned command.
CliCommand view_cli_command();

}  // namespace glint::viewer
