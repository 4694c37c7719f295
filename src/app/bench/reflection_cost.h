#pragma once
// What a frame's reflections cost, from the pass times and counters FrameLoop measured: the columns
// `glint bench --experiment adaptive` and `--experiment glossy` report (docs/bench.md). The
// reflection cost is SSR + ray list + trace + hit shading (+ auto's tile classification); the
// resolve (blur or denoiser) is kept beside it.
#include "app/frame_loop.h"

#include <string>

namespace glint::bench {

struct ReflectionCost {
  double ssr_ms = 0.0, ray_list_ms = 0.0, trace_ms = 0.0, hit_shade_ms = 0.0, classify_ms = 0.0;
  double resolve_ms = 0.0;    // fade + blur, or the denoiser (--denoise on)
  double gpu_total_ms = 0.0;  // every timed pass of the frame
  double rays = 0.0;          // rays traced (every sample of --spp)
  double reflective = 0.0;    // reflective pixels
  double reflection_ms() const { return ssr_ms + ray_list_ms + trace_ms + hit_shade_ms + classify_ms; }
};

ReflectionCost reflection_cost(const FrameMeasurement& frame);

// The first backend of a --backends list that can run here; glint::Error naming the list otherwise.
std::string first_available_backend(const std::string& backends);

}  // namespace glint::bench
