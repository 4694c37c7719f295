#version 450 core
// The gl backend's closest-hit trace (src/gl_rt/gl_ray_tracer.h, docs/ray-tracer.md "gl"): one
// invocation per ray, hits[i] = the closest hit of rays[i] in RayTracer's convention.
layout(local_size_x = 64) in;

const bool kAnyHit = false;
#include "include/gl_rt_kernel.glsl"

layout(std430, binding = 26) writeonly restrict buffer TracerHits { Hit tracer_hits[]; };

void main() {
  const uint i = ray_index();
  if (i == kInvalidIndex) return;
  const Ray ray = tracer_rays[i];
  Hit hit;
  trace_ray(ray.origin, ray.direction, ray.t_min, ray.t_max, hit);
  tracer_hits[i] = hit;
}
