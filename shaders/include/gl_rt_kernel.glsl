// What both gl backend kernels share: the ray list of one trace (RayTracer::trace_closest/trace_any
// on the host, rt::GlTracing on the renderer's GL buffers), its count, and which ray an invocation
// traces.
#include "include/gl_rt_traverse.glsl"

layout(std430, binding = 25) readonly restrict buffer TracerRays { Ray tracer_rays[]; };
// The first uint of the caller's count buffer: how many rays the list holds, read here on the GPU.
layout(std430, binding = 27) readonly restrict buffer TracerRayCount { uint tracer_ray_count; };

uniform uint ray_base;      // the first ray of this dispatch (a long list takes several)
uniform uint ray_capacity;  // at most this many rays are traced, whatever the count says

// The ray this invocation traces, or kInvalidIndex at or past min(count, capacity): those slots are
// not written.
uint ray_index() {
  const uint i = ray_base + gl_GlobalInvocationID.x;
  return i < min(tracer_ray_count, ray_capacity) ? i : kInvalidIndex;
}
