#pragma once
// The viewer's window: GLFW with an OpenGL 4.5 core context (through EGL where it can, else GLX) made
// current on this thread, which the frame pipeline renders on exactly as on the headless EGL context
// of `glint render` (it needs only a current 4.5 core context; its passes draw into their own
// framebuffers). Without a display (no
// DISPLAY, an X server that cannot be reached) construction is one glint::Error saying so (a script
// ending in `quit` runs offscreen instead, viewer_app.cpp).
#include <optional>
#include <string>

struct GLFWwindow;

namespace glint::viewer {

class GlfwWindow {
public:
  GlfwWindow(const std::string& title, int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  // Nullopt when a window can be opened; otherwise the one-line message the constructor would fail
  // with ("view: no display to open a window on (...): ..."). Leaves GLFW initialised when there is
  // a display: make the window next.
  static std::optional<std::string> why_no_display();

  GLFWwindow* handle() const { return window_; }
  bool close_requested() const;
  void poll_events();
  // Waits for an event, `seconds` at most (an idle viewer then leaves the CPU to others).
  void wait_events(double seconds);
  void swap_buffers();
  int framebuffer_width() const;
  int framebuffer_height() const;
  // Mouse-wheel notches since the last call (vertical).
  float take_scroll();
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER

private:
  GLFWwindow* window_ = nullptr;
  std::string renderer_;
  float scroll_ = 0.0f;
};

}  // namespace glint::viewer
