#pragma once
// The middle step of RayTracedReflections, between the ray-list pass and hit shading: the backend
// traces the frame's reflection rays into hit records. How depends on where the backend traces, so
// RayTracedReflections picks one step at construction (make_reflection_trace_step) and each way is
// written once, in its own file:
//   HostReflectionTrace   (cpu, embree): the CPU waits for the list, traces host-mapped buffers;
//   DeviceReflectionTrace (cuda, optix: rt::DeviceTracing): the GL buffers mapped into CUDA, no
//                         host wait; timed as the "device_trace" pass;
//   GlReflectionTrace     (gl: rt::GlTracing): compute shaders over the GL buffers, a timed GL pass.
#include "gl/gpu_timer.h"
#include "render/ray_hit_buffers.h"
#include "rt/ray_tracer.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace glint::render {

class HitShadowRays;

struct RayTraceFrameStats {
  std::uint32_t rays_traced = 0;        // rays in the list, all traced
  std::uint32_t reflective_pixels = 0;  // reflective pixels the ray-list pass saw
  // CPU backends: the backend's trace_closest, wall clock; cuda and optix: the trace kernels' GPU
  // time (CUDA events), the hits' shadow rays included where they are traced with the hits (rt and
  // hybrid shadows): the work each traced ray brings, for --reflections auto's cost model; gl: the
  // frame timer's "trace" pass (filled in by FrameLoop; 0 here). The other backends trace the hits'
  // shadow rays in the hit_shade pass.
  double trace_ms = 0.0;
  // Of trace_ms, the hits' shadow rays (cuda and optix with rt or hybrid shadows; 0 otherwise).
  double hit_shadow_trace_ms = 0.0;
};

class ReflectionTraceStep {
public:
  virtual ~ReflectionTraceStep() = default;

  // Traces the rays the ray-list pass just wrote for readback slot `slot` (run % kFramesInFlight)
  // into the hit buffer; `light_position` is for the hits' shadow rays where the backend traces them
  // with the hits. `with_the_rays` (may be empty) is other work to issue in the same hand-over, before
  // the reflection rays: the device step issues it inside its mapping and its timed pass, the others
  // just before their own trace, untimed. Returns how many list entries hit shading must look at
  // (the list's count when the host knows it, else the buffers' capacity: the GPU reads the count).
  virtual std::uint32_t trace(std::size_t slot, vec3 light_position, GpuTimer* timer,
                              const std::function<void()>& with_the_rays) = 0;
  // After hit shading was issued: queue what stats() needs of this slot (GPU steps: the counters).
  virtual void finish(std::size_t slot) = 0;
  // The statistics of the run traced into `slot`: nullopt while the GPU has not finished it and
  // `wait` is false.
  virtual std::optional<RayTraceFrameStats> stats(std::size_t slot, bool wait) = 0;
};

// Where the ray and hit buffers must live for `tracer`'s step: host-mapped for a CPU backend, GPU
// memory for the others.
RayHitMemory reflection_ray_memory(rt::RayTracer& tracer);

// The step for `tracer`'s kind of backend over `buffers` (made with reflection_ray_memory(tracer)).
// `hit_shadows` (null without shadow rays) is used where the tracer traces them with the hits. All
// three must outlive the step.
std::unique_ptr<ReflectionTraceStep> make_reflection_trace_step(rt::RayTracer& tracer, RayHitBuffers& buffers,
                                                                HitShadowRays* hit_shadows);

}  // namespace glint::render
