#pragma once
// The reflection trace of a CUDA backend (cuda, optix: rt::DeviceTracing): the GL ray, hit and
// counter buffers are mapped into CUDA on the tracer's stream and the trace reads the ray count on
// the GPU, so the host only enqueues and never waits. Where the tracer can (traces_hit_shadows),
// the hits' shadow rays are written and answered in the same CUDA work. The statistics come frames
// later: the counters from the readback slot, the trace's time from its CUDA events.
#include "cuda/gl_buffer_interop.h"
#include "render/reflection_trace_step.h"

#include <array>
#include <optional>

namespace glint::render {

class DeviceReflectionTrace final : public ReflectionTraceStep {
public:
  DeviceReflectionTrace(rt::DeviceTracing& device, RayHitBuffers& buffers, HitShadowRays* hit_shadows);

  std::uint32_t trace(std::size_t slot, vec3 light_position, GpuTimer* timer,
                      const std::function<void()>& with_the_rays) override;
  void finish(std::size_t slot) override { buffers_.request_counts(slot); }
  std::optional<RayTraceFrameStats> stats(std::size_t slot, bool wait) override;

private:
  rt::DeviceTracing& device_;
  RayHitBuffers& buffers_;
  HitShadowRays* hit_shadows_;   // null without shadow rays
  cuda::GlBufferInterop interop_;  // rays, hits, counters
  // A trace's GPU time, read once (the read frees the tracer's span) and kept for a second stats()
  // of the slot; a ticket still unread when its slot is traced again can no longer be asked for,
  // and is let go (drop).
  struct GpuTime {
    std::optional<rt::GpuTicket> unread;
    std::optional<double> ms;
    std::optional<double> read(rt::DeviceTracing& device, bool wait);  // nullopt: not there yet
    void drop(rt::DeviceTracing& device);
  };
  // Per readback slot: the closest-hit trace's time and, where traced with the hits, the hits'
  // shadow rays' (never asked for: no ticket).
  struct TraceTimes {
    GpuTime closest, hit_shadows;
  };
  std::array<TraceTimes, kFramesInFlight> times_{};
};

}  // namespace glint::render
