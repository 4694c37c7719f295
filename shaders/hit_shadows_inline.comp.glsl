#version 450 core
// The reflection hits' shadow rays, made and traced in one invocation per ray (RayTracedReflections
// with the gl backend and rt or hybrid shadows, render/gl_reflection_trace.h, docs/hybrid.md): after
// the gl backend's closest-hit kernel wrote hit i, ray i's shadow ray by include/hit_shadow_ray.glsl's
// rule, traced by the occlusion query of the gl backend's walk (include/gl_rt_traverse.glsl, bound by
// rt::GlTracing::bind_inline_tracing), answer i written where hit shading reads it. The same rays and
// answers as hit_shadow_rays.comp.glsl and gl_rt_any.comp.glsl, in one dispatch and without the
// shadow ray list between them.
// The closest hit stays in its own kernel: the two walks in one invocation made the pair 1.13 ms on an
// H100 against 0.56 as separate dispatches (docs/perf.md "Eleventh round").
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
layout(std430, binding = 8) readonly buffer Hits { Hit hits[]; };
layout(std430, binding = 9) readonly buffer RayCounters { uint ray_count; uint reflective_count; };
layout(std430, binding = 11) writeonly buffer HitShadowOccluded { uint hit_shadow_occluded[]; };

uniform uint ray_base;      // the first ray of this dispatch (a long list takes several)
uniform uint ray_capacity;  // at most this many rays are traced, whatever the count says

void main() {
  const uint i = ray_base + gl_GlobalInvocationID.x;
  if (i >= min(ray_count, ray_capacity)) return;  // slots at or past the count are not written
  const Ray shadow = hit_shadow_ray(rays[i], hits[i]);
  hit_shadow_occluded[i] =
      !is_empty(shadow) && trace_occluded(shadow.origin, shadow.direction, shadow.t_min, shadow.t_max) ? 1u : 0u;
}
