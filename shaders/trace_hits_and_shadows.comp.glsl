#version 450 core
// The reflection rays' closest hits and the hits' shadow rays in one invocation per ray
// (RayTracedReflections with the gl backend and rt or hybrid shadows, render/gl_reflection_trace.h,
// docs/hybrid.md): ray i's closest hit by the gl backend's walk (include/gl_rt_traverse.glsl, bound
// by rt::GlTracing::bind_inline_tracing), then its shadow ray by include/hit_shadow_ray.glsl's rule,
// traced by the same structures' occlusion query, answer i written where hit shading reads it. The
// same hits, rays and answers as gl_rt_closest.comp.glsl, hit_shadow_rays.comp.glsl and
// gl_rt_any.comp.glsl, in one dispatch and without the shadow ray list between them.
// A render pass, not a gl_rt kernel: the hit point comes from the renderer's GpuScene buffers (as hit
// shading rebuilds it), which gl_rt/ knows nothing of.
// One warp per work group, as the gl backend's kernels (their stacks live in local memory).
layout(local_size_x = 32) in;

#include "include/frame_constants.glsl"
#include "include/gl_rt_traverse.glsl"
#include "include/hit_shadow_ray.glsl"

// RayHitBuffers (render_targets.h) and the hits' OcclusionBuffers answers (one uint per ray,
// occlusion_flag.glsl reads them).
layout(std430, binding = 6) readonly buffer Rays { Ray rays[]; };
layout(std430, binding = 8) writeonly buffer Hits { Hit hits[]; };
layout(std430, binding = 9) readonly buffer RayCounters { uint ray_count; uint reflective_count; };
layout(std430, binding = 11) writeonly buffer HitShadowOccluded { uint hit_shadow_occluded[]; };

uniform uint ray_base;      // the first ray of this dispatch (a long list takes several)
uniform uint ray_capacity;  // at most this many rays are traced, whatever the count says

void main() {
  const uint i = ray_base + gl_GlobalInvocationID.x;
  if (i >= min(ray_count, ray_capacity)) return;  // slots at or past the count are not written
  const Ray ray = rays[i];
  const Hit hit = trace_closest(ray.origin, ray.direction, ray.t_min, ray.t_max);
  hits[i] = hit;
  const Ray shadow = hit_shadow_ray(ray, hit);
  hit_shadow_occluded[i] =
      !is_empty(shadow) && trace_occluded(shadow.origin, shadow.direction, shadow.t_min, shadow.t_max) ? 1u : 0u;
}
