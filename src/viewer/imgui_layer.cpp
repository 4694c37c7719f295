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
  if (texture_ != 0) glDeleteTextures(1, &texture_);
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::show(const ImageRgba8& image) {
  if (image.width != texture_width_ || image.height != texture_height_) {
    if (texture_ != 0) glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA8, image.width, image.height);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    texture_width_ = image.width;
    texture_height_ = image.height;
  }
  // Rows top first, as ImGui's texture coordinates expect (v = 0 at the top).
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  glTextureSubImage2D(texture_, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
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
  if (texture_ != 0 && area > 0.0f && height > 0.0f) {
    const float scale = std::min(area / static_cast<float>(texture_width_), height / static_cast<float>(texture_height_));
    const ImVec2 size(static_cast<float>(texture_width_) * scale, static_cast<float>(texture_height_) * scale);
    const ImVec2 corner(side_margin + (area - size.x) * 0.5f, (height - size.y) * 0.5f);
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture_)), corner,
                                             ImVec2(corner.x + size.x, corner.y + size.y));
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
