#include "viewer/playback.h"

#include <cmath>

namespace glint::viewer {

void advance_playback(ViewerState& state, float seconds, float frames_per_second, int frame_count) {
  if (!state.playing || frame_count <= 0) return;
  state.frame += static_cast<double>(seconds) * static_cast<double>(frames_per_second) * static_cast<double>(state.speed);
  state.frame = std::fmod(state.frame, static_cast<double>(frame_count));
}

}  // namespace glint::viewer
