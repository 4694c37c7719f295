#include "render/gl_reflection_trace.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/gpu_scene.h"
#include "render/hit_shadow_rays.h"

#include <algorithm>

namespace glint::render {
namespace {

// GL guarantees this many work groups per dispatch (as the gl backend's own kernels, which split
// longer lists the same way); the pass's work groups are one warp of 32 rays (its local size).
constexpr std::uint64_t kMaxGroupsPerDispatch = 65535;
constexpr GLuint kRaysPerGroup = 32;

}  // namespace

GlReflectionTrace::GlReflectionTrace(rt::GlTracing& gl, RayHitBuffers& buffers, HitShadowRays* hit_shadows)
    : gl_(gl), buffers_(buffers), hit_shadows_(hit_shadows) {
  if (hit_shadows_ == nullptr || !hit_shadows_->traced_with_hits()) return;
  with_shadows_.emplace(ShaderProgram::from_embedded({"hit_shadows_inline.comp.glsl"}));
  with_shadows_->set_uniform("origin_offset", hit_shadows_->origin_offset());
  ray_base_ = with_shadows_->uniform_location("ray_base");
  ray_capacity_ = with_shadows_->uniform_location("ray_capacity");
  check_gl("gl reflection trace: set-up");
}

std::uint32_t GlReflectionTrace::trace(std::size_t, const HitShadowFrame& frame, GpuTimer* timer,
                                       const std::function<void()>& with_the_rays) {
  if (with_the_rays) with_the_rays();  // GL passes all: no hand-over to share
  const auto capacity = static_cast<std::uint32_t>(buffers_.capacity());
  run_timed_pass(timer, "trace", [&] {
    gl_.trace_closest_gl(buffers_.ray_buffer(), buffers_.hit_buffer(), buffers_.counter_buffer(), capacity);
    if (with_shadows_) trace_hit_shadows(frame, capacity);
  });
  return capacity;
}

void GlReflectionTrace::trace_hit_shadows(const HitShadowFrame& frame, std::uint32_t capacity) {
  GlPassScope scope("hit_shadows");
  // The shadow rule rebuilds each hit point from the GpuScene and reads the light from the frame
  // constants, as hit_shadow_rays.comp.glsl does.
  frame.scene->bind_resources();
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, frame.frame_constants);
  buffers_.bind();
  hit_shadows_->answers().bind();
  gl_.bind_inline_tracing(with_shadows_->id());
  glProgramUniform1ui(with_shadows_->id(), ray_capacity_, capacity);
  with_shadows_->use();
  // Launched for the capacity, as trace_closest_gl: invocations at or past the count read on the GPU
  // return at once.
  const std::uint64_t rays_per_dispatch = kMaxGroupsPerDispatch * kRaysPerGroup;
  for (std::uint64_t base = 0; base < capacity; base += rays_per_dispatch) {
    glProgramUniform1ui(with_shadows_->id(), ray_base_, static_cast<GLuint>(base));
    glDispatchCompute(work_groups(std::min<std::uint64_t>(rays_per_dispatch, capacity - base), kRaysPerGroup), 1, 1);
  }
  // Hit shading reads the answers.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("gl reflection trace: the hits' shadow rays");
}

std::optional<RayTraceFrameStats> GlReflectionTrace::stats(std::size_t slot, bool wait) {
  const std::optional<RayListCounts> counts = buffers_.requested_counts(slot, wait);
  if (!counts) return std::nullopt;
  return RayTraceFrameStats{counts->rays, counts->reflective, 0.0};  // trace_ms: FrameLoop's "trace" pass
}

}  // namespace glint::render
