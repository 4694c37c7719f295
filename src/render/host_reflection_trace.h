#pragma once
// The reflection trace of a CPU backend (cpu, embree): the CPU waits for the ray list (its count
// read through the readback slot), then the backend's trace_closest reads the host-mapped rays and
// writes the host-mapped hits in place. The statistics are known at once.
#include "render/reflection_trace_step.h"

#include <array>

namespace glint::render {

class HostReflectionTrace final : public ReflectionTraceStep {
public:
  HostReflectionTrace(rt::RayTracer& tracer, RayHitBuffers& buffers) : tracer_(tracer), buffers_(buffers) {}

  std::uint32_t trace(std::size_t slot, vec3 light_position, GpuTimer* timer,
                      const std::function<void()>& with_the_rays) override;
  void finish(std::size_t) override {}
  std::optional<RayTraceFrameStats> stats(std::size_t slot, bool) override { return stats_[slot]; }

private:
  rt::RayTracer& tracer_;
  RayHitBuffers& buffers_;
  std::array<RayTraceFrameStats, kFramesInFlight> stats_{};  // per readback slot
};

}  // namespace glint::render
