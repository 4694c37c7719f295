#pragma once
// The walkthrough's clock in `glint view`: while playing, the frame advances at the walkthrough's
// frame rate times the speed and wraps at the end. Flying does not stop it: the flown camera sees
// the walkthrough's frame (deformation, light) as it plays (FrameLoop::submit's camera).
#include "viewer/viewer_state.h"

namespace glint::viewer {

// Advances state.frame by `seconds` of playback (nothing while paused).
void advance_playback(ViewerState& state, float seconds, float frames_per_second, int frame_count);

}  // namespace glint::viewer
