#pragma once
// HitShadowRays: the shadows of reflection hits with rt and hybrid shadows (docs/hybrid.md). After
// the closest-hit trace of the reflection rays, one compute pass (shaders/hit_shadow_rays.comp.glsl)
// writes a shadow ray from each hit point towards the light into slot i of OcclusionBuffers (i: the
// reflection ray's index), and the tracer's occlusion query answers them; HitShadingPass then reads
// ray i's answer instead of looking the hit up in the cube map, so reflected shadows are exact too.
// A GPU backend that traces the hits' shadow rays with the hits (rt::DeviceTracing::
// traces_hit_shadows: cuda) writes and answers them in the closest-hit trace's CUDA work instead
// (RayTracedReflections maps answers() for it), by the same rule (rt/hit_shadow_ray.h), which saves
// a GL pass and a GL-CUDA hand-over between the two traces; run() then does nothing.
//   inputs:  RayHitBuffers (rays, hits, counters), GpuScene, FrameConstants UBO (light)
//   outputs: OcclusionBuffers rays and answers, slot i for reflection ray i
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/occlusion_buffers.h"
#include "render/ray_hit_buffers.h"
#include "rt/ray_tracer.h"

#include <epoxy/gl.h>

#include <cstdint>

namespace glint::render {

class HitShadowRays {
public:
  // Room for `capacity` rays (the reflection buffers'); `tracer` must outlive this; origin_offset:
  // world distance along the normal (>= 0, finite). Needs a current GL context.
  HitShadowRays(std::size_t capacity, rt::RayTracer& tracer, float origin_offset);

  // Writes and traces the shadow rays of the reflection hits in `buffers`: `max_rays` slots (the
  // list's count when the host knows it, CPU backends; else the capacity, the shader reading the
  // count), of which a CPU backend traces the first `max_rays`.
  void run(RayHitBuffers& buffers, const GpuScene& scene, GLuint frame_constants, std::uint32_t max_rays);

  const OcclusionBuffers& answers() const { return buffers_; }
  OcclusionBuffers& answers() { return buffers_; }
  // Whether the tracer writes and traces them within its closest-hit trace (run() does nothing).
  bool traced_with_hits() const { return traced_with_hits_; }
  float origin_offset() const { return origin_offset_; }

private:
  OcclusionBuffers buffers_;
  float origin_offset_;
  bool traced_with_hits_;
  ShaderProgram program_;
};

}  // namespace glint::render
