#include "viewer/view_command.h"

#include "app/info_command.h"
#include "core/error.h"
#include "viewer/viewer_app.h"
#include "viewer/viewer_settings.h"

#include <memory>

namespace glint::viewer {

void add_view_command(CLI::App& app, ViewOptions& options) {
  CLI::App* command = app.add_subcommand(
      "view", "Open a window on a scene's walkthrough: fly or follow the path, switch settings live, see every "
              "intermediate image (docs/viewer.md)");
  command->add_option("scene", options.render.scene, "Preset (atrium, atrium-simple, sponza) or scene file")
      ->capture_default_str();
  command->add_option("--width", options.render.width, "Render width in pixels (before the resolution scale)")
      ->check(CLI::Range(16, 16384))
      ->capture_default_str();
  command->add_option("--height", options.render.height, "Render height in pixels (before the resolution scale)")
      ->check(CLI::Range(16, 16384))
      ->capture_default_str();
  command->add_option("--frame", options.frame, "Walkthrough frame shown first")->check(CLI::NonNegativeNumber);
  command->add_option("--set", options.settings,
                      "A starting setting NAME=VALUE, as the script's `set NAME VALUE` (repeatable), e.g. "
                      "--set reflections=rt --set backend=embree")
      ->allow_extra_args(false);  // one NAME=VALUE per --set, so a scene after it stays the scene
  command->add_option("--script", options.script,
                      "Run the commands of FILE (set, frame, play, pause, camera, path, wait, screenshot, record, "
                      "reload, quit; docs/viewer.md)");
  command->add_flag("--offscreen", options.offscreen,
                    "Run the --script without a window, on a headless EGL context as `glint render` (NVIDIA's GPU "
                    "on a GPU machine with no X server); the script must end with quit. Chosen by itself when "
                    "there is no display");
  add_flat_normals_flag(*command, options.render.flat_normals);
}

int run_view_command(const ViewOptions& options) {
  ViewerLaunch launch;
  launch.options = options.render;
  for (const std::string& setting : options.settings) {
    const std::size_t equals = setting.find('=');
    if (equals == std::string::npos) fail("--set {}: expected NAME=VALUE", setting);
    try {
      set_viewer_setting(launch.options, setting.substr(0, equals), setting.substr(equals + 1));
    } catch (const Error& error) {
      fail("--set {}", error.what());
    }
  }
  (void)render_pipeline_settings(launch.options);  // a bad combination is one line before the window opens
  launch.script = options.script;
  launch.frame = options.frame;
  launch.offscreen = options.offscreen;
  return run_viewer(launch);
}

CliCommand view_cli_command() {
  const auto options = std::make_shared<ViewOptions>();
  return {"view", [options](CLI::App& app) { add_view_command(app, *options); },
          [options] { return run_view_command(*options); }};
}

}  // namespace glint::viewer
