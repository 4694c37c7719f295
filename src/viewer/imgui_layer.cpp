#include "viewer/imgui_layer.h"

#include "viewer/glfw_window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdint>

namespace glint::viewer {

ImGuiLayer::ImGuiLayer(GlfwWindow& window) : window_(&window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.handle(), /*install_callbacks=*/true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::begin_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::end_frame(float side_margin) {
  // ImGui draws in window coordinates (DisplaySize), which are not pixels on a high-DPI screen.
  const float width = ImGui::GetIO().DisplaySize.x;
  const float height = ImGui::GetIO().DisplaySize.y;
  const float area = width - 2.0f * side_margin;
  if (picture_.id() != 0 && area > 0.0f && height > 0.0f) {
    const float picture_width = static_cast<float>(picture_.width());
    const float picture_height = static_cast<float>(picture_.height());
    const float scale = std::min(area / picture_width, height / picture_height);
    const ImVec2 size(picture_width * scale, picture_height * scale);
    const ImVec2 corner(side_margin + (area - size.x) * 0.5f, (height - size.y) * 0.5f);
    // ImGui's v = 0 is the top of the rectangle: a GPU copy (bottom row first) is drawn with v flipped.
    const bool flip = picture_.bottom_row_first();
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(picture_.id())),
                                             corner, ImVec2(corner.x + size.x, corner.y + size.y),
                                             ImVec2(0.0f, flip ? 1.0f : 0.0f), ImVec2(1.0f, flip ? 0.0f : 1.0f));
  }
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, window_->framebuffer_width(), window_->framebuffer_height());
  glDisable(GL_FRAMEBUFFER_SRGB);  // the picture is sRGB-encoded already
  glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace glint::viewer
