#include "render/reflection_trace_step.h"

#include "render/device_reflection_trace.h"
#include "render/gl_reflection_trace.h"
#include "render/host_reflection_trace.h"

namespace glint::render {

RayHitMemory reflection_ray_memory(rt::RayTracer& tracer) {
  return tracer.device_tracing() || tracer.gl_tracing() ? RayHitMemory::device : RayHitMemory::host_mapped;
}

std::unique_ptr<ReflectionTraceStep> make_reflection_trace_step(rt::RayTracer& tracer, RayHitBuffers& buffers,
                                                                HitShadowRays* hit_shadows) {
  if (rt::DeviceTracing* device = tracer.device_tracing())
    return std::make_unique<DeviceReflectionTrace>(*device, buffers, hit_shadows);
  if (rt::GlTracing* gl = tracer.gl_tracing()) return std::make_unique<GlReflectionTrace>(*gl, buffers);
  return std::make_unique<HostReflectionTrace>(tracer, buffers);
}

}  // namespace glint::render
