#pragma once
// The GPU time of one piece of GL work, measured there and then: the host waits for the result, so
// this is for one-off measurements before or between frames (a choice made at set-up, such as
// PrimaryVisibility::automatic's), never for a frame's passes (GpuTimer's ring does not stall).
#include <functional>

namespace glint {

// Milliseconds of `work`'s GL commands by a GL_TIME_ELAPSED query around them (none may be active
// already: GL time queries cannot nest). Meaningless on Mesa's software rasterisers (gpu_timer.h).
double time_gl_work_ms(const std::function<void()>& work);

}  // namespace glint
