#version 450 core
// The gl backend's closest-hit trace (src/gl_rt/gl_ray_tracer.h, docs/ray-tracer.md "gl"): one
// invocation per ray, hits[i] = the closest hit of rays[i] in RayTracer's convention.
// One warp per work group: the walk's per-invocation stacks live in local memory, and groups of 32
// traced 20-25 % faster than groups of 64 (and groups of 128 slower still) on the H200 (docs/perf.md,
// "The gl backend's traversal"). The host reads the size from the program.
layout(local_size_x = 32) in;

#include "include/gl_rt_kernel.glsl"

layout(std430, binding = 26) writeonly restrict buffer TracerHits { Hit tracer_hits[]; };

void main() {
  const uint i = ray_index();
  if (i == kInvalidIndex) return;
  const Ray ray = tracer_rays[i];
  tracer_hits[i] = trace_closest(ray.origin, ray.direction, ray.t_min, ray.t_max);
}
