#pragma once
// The reflection trace of a CUDA backend (cuda, optix: rt::DeviceTracing): the GL ray, hit and
// counter buffers are mapped into CUDA on the tracer's stream and the trace reads the ray count on
// the GPU, so the host only enqueues and never waits. Where the tracer can (traces_hit_shadows),
// the hits' shadow rays are written and answered in the same CUDA work. The statistics come frames
// later: the counters from the readback slot, the trace's time from its CUDA events.
#include "cuda/gl_buffer_interop.h"
#include "render/reflection_trace_step.h"

#include <array>

namespace glint::render {

class DeviceReflectionTrace final : public ReflectionTraceStep {
public:
  DeviceReflectionTrace(rt::DeviceTracing& device, RayHitBuffers& buffers, HitShadowRays* hit_shadows);

  std::uint32_t trace(std::size_t slot, vec3 light_position, GpuTimer* timer) override;
  void finish(std::size_t slot) override { buffers_.request_counts(slot); }
  std::optional<RayTraceFrameStats> stats(std::size_t slot, bool wait) override;

private:
  rt::DeviceTracing& device_;
  RayHitBuffers& buffers_;
  HitShadowRays* hit_shadows_;   // null without shadow rays
  cuda::GlBufferInterop interop_;  // rays, hits, counters
  std::array<rt::GpuTicket, kFramesInFlight> tickets_{};  // per readback slot: the trace's GPU span
};

}  // namespace glint::render
