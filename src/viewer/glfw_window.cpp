#include "viewer/glfw_window.h"

#include "core/error.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include <fmt/format.h>

#include <cstdlib>

namespace glint::viewer {
namespace {

std::string last_glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  std::string text = description != nullptr ? description : "no reason given";
  while (!text.empty() && text.back() == ' ') text.pop_back();  // GLFW ends some messages with a blank
  return text;
}

std::string no_display_message() {
  const char* display = std::getenv("DISPLAY");
  return fmt::format(
      "view: no display to open a window on ({}; DISPLAY is {}): run it on a desktop, over ssh -X, or under "
      "xvfb-run -a (a --script ending in quit runs offscreen without one)",
      last_glfw_error(), display != nullptr && *display != '\0' ? display : "not set");
}

}  // namespace

std::optional<std::string> GlfwWindow::why_no_display() {
  if (glfwInit() == GLFW_FALSE) return no_display_message();
  // GLFW stays initialised (the window's glfwInit is then a no-op, its destructor terminates): closing
  // the display connection here would let an X server without -noreset (Xvfb, xvfb-run) reset, and
  // the window's connection a moment later could fail.
  return std::nullopt;
}

GlfwWindow::GlfwWindow(const std::string& title, int width, int height) {
  if (glfwInit() == GLFW_FALSE) fail("{}", no_display_message());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // EGL first, as `glint render` uses (the gl backend asks EGL for the current context); the display
  // system's native API (GLX) where EGL cannot make a window context, or where GLINT_WINDOW_GL=glx
  // asks for it (VirtualGL moves GLX contexts to the GPU, not EGL/X11 ones; docs/gl.md).
  const char* asked = std::getenv("GLINT_WINDOW_GL");
  const bool glx_only = asked != nullptr && std::string(asked) == "glx";
  std::string egl_reason = "skipped (GLINT_WINDOW_GL=glx)";
  if (!glx_only) {
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) egl_reason = last_glfw_error();
  }
  if (window_ == nullptr) {
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_NATIVE_CONTEXT_API);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
      const std::string native_reason = last_glfw_error();
      glfwTerminate();
      fail("view: the display gives no OpenGL 4.5 core context (EGL: {}; native: {})", egl_reason, native_reason);
    }
  }
  glfwSetWindowUserPointer(window_, this);
  // Set before ImGui's backend installs its callbacks, which call this one after its own.
  glfwSetScrollCallback(window_, [](GLFWwindow* window, double, double y) {
    static_cast<GlfwWindow*>(glfwGetWindowUserPointer(window))->scroll_ += static_cast<float>(y);
  });
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(0);  // frames as fast as they render: the stats measure the renderer, not the display
  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool GlfwWindow::close_requested() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void GlfwWindow::poll_events() { glfwPollEvents(); }
void GlfwWindow::wait_events(double seconds) { glfwWaitEventsTimeout(seconds); }
void GlfwWindow::swap_buffers() { glfwSwapBuffers(window_); }

int GlfwWindow::framebuffer_width() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return width;
}

int GlfwWindow::framebuffer_height() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return height;
}

float GlfwWindow::take_scroll() {
  const float notches = scroll_;
  scroll_ = 0.0f;
  return notches;
}

}  // namespace glint::viewer
