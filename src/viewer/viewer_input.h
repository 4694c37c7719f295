#pragma once
// Keys and mouse of the viewer's window: Space plays or pauses, F starts flying from the current
// camera, R returns to the walkthrough's camera, P takes a screenshot; while flying W/A/S/D move,
// Q/E go down and up, dragging with the right mouse button looks around and the wheel sets the speed.
// Keys the panels are typing into, and the mouse over a panel, are left to the panels.
#include "viewer/viewer_state.h"

#include <array>

struct GLFWwindow;

namespace glint::viewer {

class ViewerInput {
public:
  // Applies one frame's input (`seconds` since the last) to `state`; `scroll` is the wheel's notches.
  void update(GLFWwindow* window, float seconds, float scroll, bool panels_want_mouse, bool panels_want_keyboard,
              ViewerState& state, ViewerRequests& requests);

private:
  bool pressed_now(GLFWwindow* window, int key);  // down now and not at the last update
  std::array<bool, 512> down_{};
  bool looking_ = false;
  double last_x_ = 0.0, last_y_ = 0.0;
};

}  // namespace glint::viewer
