#include "viewer/viewer_input.h"

#include <GLFW/glfw3.h>

namespace glint::viewer {

bool ViewerInput::pressed_now(GLFWwindow* window, int key) {
  const bool down = glfwGetKey(window, key) == GLFW_PRESS;
  bool& was = down_[static_cast<std::size_t>(key)];
  const bool pressed = down && !was;
  was = down;
  return pressed;
}

void ViewerInput::update(GLFWwindow* window, float seconds, float scroll, bool panels_want_mouse,
                         bool panels_want_keyboard, ViewerState& state, ViewerRequests& requests) {
  if (!panels_want_keyboard) {
    if (pressed_now(window, GLFW_KEY_SPACE)) state.playing = !state.playing;
    if (pressed_now(window, GLFW_KEY_F)) requests.start_flying = true;
    if (pressed_now(window, GLFW_KEY_R)) requests.back_to_path = true;
    if (pressed_now(window, GLFW_KEY_P)) requests.screenshot = true;
    if (state.flying) {
      vec3 direction(0.0f);
      const auto held = [&](int key) { return glfwGetKey(window, key) == GLFW_PRESS ? 1.0f : 0.0f; };
      direction.z = held(GLFW_KEY_W) - held(GLFW_KEY_S);
      direction.x = held(GLFW_KEY_D) - held(GLFW_KEY_A);
      direction.y = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
      state.fly.move(direction, seconds);
    }
  }
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool right = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (state.flying && right && (looking_ || !panels_want_mouse)) {
    if (looking_) state.fly.turn(static_cast<float>(x - last_x_), static_cast<float>(y - last_y_));
    looking_ = true;
  } else {
    looking_ = false;
  }
  last_x_ = x;
  last_y_ = y;
  if (state.flying && !panels_want_mouse && scroll != 0.0f) state.fly.scroll(scroll);
}

}  // namespace glint::viewer
