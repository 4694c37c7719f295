#pragma once
// What the person (or the script) controls in `glint view`, shared by the panels, the keys and the
// script runner; the app turns it into renders (viewer_app.cpp).
#include "app/render_command.h"
#include "viewer/fly_camera.h"

#include <string>

namespace glint::viewer {

struct ViewerState {
  RenderOptions options;  // the renderer's settings; width and height before the scale
  float scale = 1.0f;     // resolution scale: the frame is rendered at width x height times this
  double frame = 0.0;     // walkthrough frame (fractional while playing; the integer part is shown)
  bool playing = false;
  float speed = 1.0f;     // playback: the walkthrough's frame rate times this
  bool flying = false;    // free camera instead of the walkthrough's
  FlyCamera fly;
  bool light_stays = false;  // the light stays where it is instead of following its path
  std::string view = "final";
  bool continuous = true;    // render every frame even when nothing changed (live timings)
  std::string screenshot_path = "glint-view.png";
  std::string record_path;   // where `record save` writes; empty: next to the scene file
  std::string status;        // the last message (errors of a setting, files written)
};

// What the panels or keys asked for this frame, beyond changing the state.
struct ViewerRequests {
  bool screenshot = false;
  bool reload = false;
  bool start_flying = false;  // from the walkthrough camera where it is now
  bool back_to_path = false;
  bool record_toggle = false;
  bool record_save = false;
};

}  // namespace glint::viewer
