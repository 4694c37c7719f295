#pragma once
// `glint view`'s main loop: a window (glfw_window.h), panels (viewer_panels.h), keys and mouse
// (viewer_input.h), an optional script (viewer_script.h), and the renders of a ViewerSession (the
// frame loop of `glint render`). Each turn: events, the script's next commands, input and panels,
// the settings and light pushed to the session, a render when something changed (every turn with
// "render continuously"), the picture and panels drawn.
#include "app/render_command.h"

#include <filesystem>

namespace glint::viewer {

struct ViewerLaunch {
  RenderOptions options;         // scene and starting settings (width and height: the render size)
  std::filesystem::path script;  // empty: interactive only
  int frame = 0;                 // the walkthrough frame shown first
  // No window: the script runs on a headless EGL context (gl/egl_context.h, as `glint render`), to
  // its `quit`. Also chosen when a script is given and there is no display.
  bool offscreen = false;
};

// Returns the exit status: 0 after `quit` or the window closed, 128 + the signal after SIGINT or
// SIGTERM (the screenshot being written is finished first). glint::Error for no display (where a
// window is needed: no script, or one without `quit`), a bad script line ("FILE:LINE: ...") or a
// scene that does not load.
int run_viewer(const ViewerLaunch& launch);

}  // namespace glint::viewer
