#include "render/hit_shadow_rays.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"

#include <cmath>

namespace glint::render {
namespace {

constexpr GLuint kWorkGroupSize = 64;  // local_size_x in hit_shadow_rays.comp.glsl

}  // namespace

HitShadowRays::HitShadowRays(std::size_t capacity, rt::RayTracer& tracer, float origin_offset)
    : buffers_(capacity, tracer, "reflection shadow rays"),
      origin_offset_(origin_offset),
      traced_with_hits_(tracer.device_tracing() != nullptr && tracer.device_tracing()->traces_hit_shadows()),
      program_(ShaderProgram::from_embedded({"hit_shadow_rays.comp.glsl"})) {
  if (!(origin_offset >= 0.0f) || !std::isfinite(origin_offset))
    fail("reflection shadow rays: origin offset {} must be finite and >= 0", origin_offset);
  program_.set_uniform("origin_offset", origin_offset);
  check_gl("reflection shadow rays: set-up");
}

void HitShadowRays::run(RayHitBuffers& buffers, const GpuScene& scene, GLuint frame_constants,
                        std::uint32_t max_rays) {
  GlPassScope scope("hit_shadow_rays");
  if (max_rays > buffers_.capacity())
    fail("reflection shadow rays: {} rays, more than the capacity {}", max_rays, buffers_.capacity());
  if (max_rays == 0 || traced_with_hits_) return;
  scene.bind_resources();
  buffers.bind();
  buffers_.bind();
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, frame_constants);
  program_.set_uniform("max_rays", static_cast<int>(max_rays));
  // The gl backend traces only the list's count (read on the GPU from the ray counters), so the
  // slots past it need no empty ray: in a hybrid frame most of the capacity (on an H100 that was
  // 29.5 MB of empty rays written and 0.8 M walks that ended at once, a frame at 1280x720). A
  // device backend (optix) traces the capacity: the empty rays are what it finds there.
  const bool gl_counts = buffers_.traces_on_gl();
  program_.set_uniform("empty_past_count", gl_counts ? 0 : 1);
  program_.use();
  { GlPassScope stage("ray_generation"); glDispatchCompute(work_groups(max_rays, kWorkGroupSize), 1, 1); }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  { GlPassScope stage("trace"); buffers_.trace(max_rays, gl_counts ? buffers.counter_buffer() : 0); }
  check_gl("reflection shadow rays");
}

}  // namespace glint::render
