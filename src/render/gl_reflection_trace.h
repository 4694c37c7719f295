#pragma once
// The reflection trace of the gl backend (rt::GlTracing): its compute shaders read the rays and the
// count from the GL buffers and write the hits there, a GL pass timed as "trace" by the frame's
// timer (FrameLoop makes that pass's time the frame's trace_ms). No host wait, no CUDA.
#include "render/reflection_trace_step.h"

namespace glint::render {

class GlReflectionTrace final : public ReflectionTraceStep {
public:
  GlReflectionTrace(rt::GlTracing& gl, RayHitBuffers& buffers) : gl_(gl), buffers_(buffers) {}

  std::uint32_t trace(std::size_t slot, vec3 light_position, GpuTimer* timer,
                      const std::function<void()>& with_the_rays) override;
  void finish(std::size_t slot) override { buffers_.request_counts(slot); }
  std::optional<RayTraceFrameStats> stats(std::size_t slot, bool wait) override;

private:
  rt::GlTracing& gl_;
  RayHitBuffers& buffers_;
};

}  // namespace glint::render
