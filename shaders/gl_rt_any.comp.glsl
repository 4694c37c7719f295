#version 450 core
// The gl backend's occlusion query (src/gl_rt/gl_ray_tracer.h, docs/ray-tracer.md "gl"): one
// invocation per ray, occluded[i] = 1 when rays[i] hits anything within [t_min, t_max], else 0;
// the walk returns at the first hit.
// One warp per work group: the walk's per-invocation stacks live in local memory, and groups of 32
// traced 20-25 % faster than groups of 64 (and groups of 128 slower still) on the H200 (docs/perf.md,
// "The gl backend's traversal"). The host reads the size from the program.
layout(local_size_x = 32) in;

#include "include/gl_rt_kernel.glsl"

layout(std430, binding = 26) writeonly restrict buffer TracerOccluded { uint tracer_occluded[]; };

void main() {
  const uint i = ray_index();
  if (i == kInvalidIndex) return;
  const Ray ray = tracer_rays[i];
  tracer_occluded[i] = trace_occluded(ray.origin, ray.direction, ray.t_min, ray.t_max) ? 1u : 0u;
}
