#pragma once
// The reflection trace of the gl backend (rt::GlTracing): its compute shaders read the rays and the
// count from the GL buffers and write the hits there, a GL pass timed as "trace" by the frame's
// timer (FrameLoop makes that pass's time the frame's trace_ms). No host wait, no CUDA.
// With shadow rays traced with the hits (HitShadowRays::traced_with_hits: rt and hybrid shadows,
// RayTracingSettings::gl_inline_shadow_rays), the closest-hit kernel is followed by one render pass
// that makes and traces the hits' shadow rays (shaders/hit_shadows_inline.comp.glsl, walking the
// tracer's structures inline): its answers go where hit shading reads them, and HitShadowRays' own
// pass and trace are skipped. trace_ms then holds the shadow rays too, as with the cuda backend.
// Two dispatches, not one: the closest-hit and occlusion walks in one kernel took twice as long on an
// H100 (docs/perf.md "Eleventh round").
#include "gl/shader_program.h"
#include "render/reflection_trace_step.h"

#include <optional>

namespace glint::render {

class GlReflectionTrace final : public ReflectionTraceStep {
public:
  // `hit_shadows` (may be null) must outlive the step.
  GlReflectionTrace(rt::GlTracing& gl, RayHitBuffers& buffers, HitShadowRays* hit_shadows);

  std::uint32_t trace(std::size_t slot, const HitShadowFrame& frame, GpuTimer* timer,
                      const std::function<void()>& with_the_rays) override;
  void finish(std::size_t slot) override { buffers_.request_counts(slot); }
  std::optional<RayTraceFrameStats> stats(std::size_t slot, bool wait) override;

private:
  void trace_hit_shadows(const HitShadowFrame& frame, std::uint32_t capacity);

  rt::GlTracing& gl_;
  RayHitBuffers& buffers_;
  HitShadowRays* hit_shadows_;  // null without shadow rays
  std::optional<ShaderProgram> with_shadows_;  // hit_shadows_inline.comp.glsl, where traced with the hits
  GLint ray_base_ = -1, ray_capacity_ = -1;      // its uniforms (uint)
};

}  // namespace glint::render
