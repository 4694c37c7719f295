#version 450 core
// Shadow rays from reflection hits (RayTracedReflections with rt or hybrid shadows, docs/hybrid.md):
// one per listed reflection ray i by include/hit_shadow_ray.glsl's rule, written to shadow ray i, so
// hit shading reads ray i's answer; the tracer's occlusion query answers them. Slots past the list's
// count (a GPU backend's dispatch covers the capacity) get an empty ray, which is never occluded.
// The gl backend makes and traces these rays in one pass instead (hit_shadows_inline.comp.glsl)
// unless asked for the three steps.
layout(local_size_x = 64) in;

#include "include/frame_constants.glsl"
#include "include/hit_shadow_ray.glsl"

layout(std430, binding = 6) readonly buffer Rays { Ray rays[]; };
layout(std430, binding = 8) readonly buffer Hits { Hit hits[]; };
layout(std430, binding = 9) readonly buffer RayCounters { uint ray_count; uint reflective_count; };
layout(std430, binding = 10) writeonly buffer ShadowRays { Ray shadow_rays[]; };

uniform int max_rays;  // the dispatch's extent: the count (CPU backends) or the capacity

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uint(max_rays)) return;
  shadow_rays[i] = i < ray_count ? hit_shadow_ray(rays[i], hits[i]) : empty_hit_shadow_ray();
}
