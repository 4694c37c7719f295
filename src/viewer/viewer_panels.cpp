#include "viewer/viewer_panels.h"

#include "viewer/viewer_script.h"
#include "viewer/viewer_settings.h"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <optional>
#include <variant>

namespace glint::viewer {
namespace {

// A combo over `choices` for a text field; returns whether the value changed.
bool choice_combo(const char* label, std::string& value, const std::vector<std::string>& choices) {
  bool changed = false;
  if (ImGui::BeginCombo(label, value.c_str())) {
    for (const std::string& choice : choices) {
      if (ImGui::Selectable(choice.c_str(), choice == value) && choice != value) {
        value = choice;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// The panels' first places: Walkthrough and Settings in a column on the left, View and Stats on the
// right, the picture between them (ImGuiLayer fits it there); the person may move them afterwards.
// Controls leave room for their labels ("shadow-cube-draw") in a kPanelWidth column.
constexpr float kControlWidth = 170.0f;

void place_next(bool right, float top, float height) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(right ? display.x - kPanelWidth : 0.0f, top), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, height), ImGuiCond_FirstUseEver);
}

void walkthrough_panel(const PanelContext& context, ViewerState& state, ViewerRequests& requests) {
  place_next(false, 0.0f, 250.0f);
  ImGui::Begin("Walkthrough");
  ImGui::PushItemWidth(kControlWidth);
  if (ImGui::Button(state.playing ? "Pause" : "Play")) state.playing = !state.playing;
  ImGui::SameLine();
  if (state.flying) {
    if (ImGui::Button("Back to path")) requests.back_to_path = true;
  } else if (ImGui::Button("Fly")) {
    requests.start_flying = true;
  }
  int frame = static_cast<int>(state.frame);
  if (ImGui::SliderInt("frame", &frame, 0, context.frame_count - 1)) state.frame = frame;
  ImGui::SliderFloat("speed", &state.speed, 0.1f, 8.0f, "%.2fx");
  if (state.flying)
    ImGui::Text("flying at %.2f m/s (WASD, Q/E, right drag, wheel)", static_cast<double>(state.fly.speed()));
  ImGui::Checkbox("light stays", &state.light_stays);
  bool deform = state.options.deform == "on";
  if (ImGui::Checkbox("deformation", &deform)) state.options.deform = deform ? "on" : "off";
  if (ImGui::Button(context.recording ? "Stop recording" : "Record path")) requests.record_toggle = true;
  ImGui::SameLine();
  ImGui::Text("%zu points", context.recorded_points);
  ImGui::InputText("record file", &state.record_path);
  if (ImGui::Button("Save path to scene file")) requests.record_save = true;
  if (ImGui::Button("Reload scene")) requests.reload = true;
  ImGui::PopItemWidth();
  ImGui::End();
}

void settings_panel(const PanelContext& context, ViewerState& state) {
  place_next(false, 250.0f, ImGui::GetIO().DisplaySize.y - 250.0f);
  ImGui::Begin("Settings");
  ImGui::PushItemWidth(kControlWidth);
  ImGui::TextUnformatted(context.renderer.c_str());
  // Every new scale rebuilds the loop, so a drag applies once, when the slider is let go.
  static std::optional<float> dragged_scale;
  float scale = dragged_scale.value_or(state.scale);
  ImGui::SliderFloat("resolution scale", &scale, 0.25f, 2.0f, "%.2f");
  if (ImGui::IsItemDeactivatedAfterEdit()) state.scale = scale;
  dragged_scale = ImGui::IsItemActive() ? std::optional<float>(scale) : std::nullopt;
  ImGui::Checkbox("render continuously", &state.continuous);
  for (const ViewerSetting& setting : viewer_settings()) {
    const std::string label(setting.label.empty() ? setting.name : setting.label);
    if (const auto* text = std::get_if<std::string RenderOptions::*>(&setting.field)) {
      if (setting.name == "deform") continue;  // a checkbox in Walkthrough
      choice_combo(label.c_str(), state.options.*(*text), setting.name == "backend" ? context.backends : setting.choices);
    } else if (const auto* integer = std::get_if<int RenderOptions::*>(&setting.field)) {
      int value = state.options.*(*integer);
      if (ImGui::InputInt(label.c_str(), &value, 1, 16, ImGuiInputTextFlags_EnterReturnsTrue))
        state.options.*(*integer) = std::clamp(value, static_cast<int>(setting.min), static_cast<int>(setting.max));
    } else {
      float value = state.options.*std::get<float RenderOptions::*>(setting.field);
      if (ImGui::InputFloat(label.c_str(), &value, 0.0f, 0.0f, setting.format, ImGuiInputTextFlags_EnterReturnsTrue))
        state.options.*std::get<float RenderOptions::*>(setting.field) =
            std::clamp(value, static_cast<float>(setting.min), static_cast<float>(setting.max));
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

void view_panel(const PanelContext& context, ViewerState& state, ViewerRequests& requests) {
  place_next(true, 0.0f, 170.0f);
  ImGui::Begin("View");
  ImGui::PushItemWidth(kControlWidth);
  choice_combo("picture", state.view, view_names());
  if (context.difference != nullptr)
    ImGui::Text("against rt: SSIM %.4f, PSNR %.2f dB", context.difference->ssim, context.difference->psnr);
  ImGui::InputText("screenshot", &state.screenshot_path);
  if (ImGui::Button("Screenshot (P)")) requests.screenshot = true;
  if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
  ImGui::PopItemWidth();
  ImGui::End();
}

void stats_panel(const PanelContext& context) {
  place_next(true, 170.0f, ImGui::GetIO().DisplaySize.y - 170.0f);
  ImGui::Begin("Stats");
  ImGui::PushItemWidth(kControlWidth);
  const StatsHistory& stats = *context.stats;
  ImGui::Text("%.1f frames per second", stats.frames_per_second());
  if (const auto& last = stats.last()) {
    ImGui::TextWrapped("frame %d: GPU passes %.2f ms, latency %.2f ms", last->frame,
                static_cast<double>(stats.gpu_total_series().empty() ? 0.0f : stats.gpu_total_series().back()),
                last->latency_ms);
    if (last->ray_stats)
      ImGui::Text("rays traced %u, trace %.2f ms", last->ray_stats->rays_traced, last->ray_stats->trace_ms);
    if (last->accel_update_ms) ImGui::Text("structure update %.2f ms", *last->accel_update_ms);
    if (last->ssr_counts)
      ImGui::Text("SSR failed %u of %u reflective pixels", last->ssr_counts->failed,
                  last->ssr_counts->reflective);
    if (last->gpu_memory_used_bytes)
      ImGui::Text("GPU memory in use %.0f MB", static_cast<double>(*last->gpu_memory_used_bytes) / 1048576.0);
    else
      ImGui::TextUnformatted("GPU memory: not reported by this driver");
  }
  const std::vector<float>& total = stats.gpu_total_series();
  if (!total.empty())
    ImGui::PlotLines("GPU ms", total.data(), static_cast<int>(total.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
  for (const auto& [name, series] : stats.pass_series()) {
    const std::string label = fmt::format("{} {:.2f} ms", name, series.empty() ? 0.0f : series.back());
    ImGui::PlotLines(label.c_str(), series.data(), static_cast<int>(series.size()), 0, nullptr, 0.0f, FLT_MAX,
                     ImVec2(0, 30));
  }
  ImGui::PopItemWidth();
  ImGui::End();
}

}  // namespace

void draw_panels(const PanelContext& context, ViewerState& state, ViewerRequests& requests) {
  walkthrough_panel(context, state, requests);
  settings_panel(context, state);
  view_panel(context, state, requests);
  stats_panel(context);
}

}  // namespace glint::viewer
