#pragma once
// `glint devices`: the CUDA GPUs glint sees and the OpenGL context it would render with, so a user
// can check a machine before a long run (and every benchmark can name its device).
#include <CLI/CLI.hpp>

namespace glint {

struct DevicesOptions {
  bool json = false;
};

void add_devices_command(CLI::App& app, DevicesOptions& options);
int run_devices_command(const DevicesOptions& options);

}  // namespace glint
