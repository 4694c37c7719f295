#pragma once
// Dear ImGui on the viewer's window (Debian's libimgui: its GLFW and OpenGL 3 backends), and the
// texture the current picture is shown from (picture_texture.h). begin_frame() starts the panels;
// end_frame() draws the picture behind them, fitted to the window with its aspect kept, upright,
// then the panels.
#include "viewer/picture_texture.h"

#include <epoxy/gl.h>

namespace glint::viewer {

class GlfwWindow;

class ImGuiLayer {
public:
  explicit ImGuiLayer(GlfwWindow& window);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  // The picture shown behind the panels: copy or upload into it to replace it.
  PictureTexture& picture() { return picture_; }
  void begin_frame();
  // Draws the picture fitted between `side_margin` pixels on the left and right (the panel columns).
  void end_frame(float side_margin);
  // Whether the panels take the mouse or the keyboard now (the camera then ignores them).
  bool wants_mouse() const;
  bool wants_keyboard() const;

private:
  GlfwWindow* window_;
  PictureTexture picture_;
};

}  // namespace glint::viewer
