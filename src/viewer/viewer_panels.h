#pragma once
// The Dear ImGui panels of `glint view`: Walkthrough (play, pause, frame, speed, fly, back to path,
// light, recording, reload), Settings (every row of viewer_settings.h, resolution scale), View (the
// picture shown; SSIM and PSNR of the difference from rt), Stats (FPS, per-pass GPU times as rolling
// graphs, rays, structure update, memory) and Screenshot. They edit the state and raise requests;
// the app applies both after the frame.
#include "viewer/frame_images.h"
#include "viewer/stats_history.h"
#include "viewer/viewer_state.h"

#include <string>
#include <vector>

namespace glint::viewer {

// Width of the panel columns on either side of the picture, in pixels.
inline constexpr float kPanelWidth = 330.0f;

struct PanelContext {
  int frame_count = 1;
  std::string renderer;              // GL_RENDERER
  std::vector<std::string> backends;  // available_backends()
  bool recording = false;
  std::size_t recorded_points = 0;
  const DifferenceFromRt* difference = nullptr;  // of the frame shown, when computed
  const StatsHistory* stats = nullptr;
};

void draw_panels(const PanelContext& context, ViewerState& state, ViewerRequests& requests);

}  // namespace glint::viewer
