#include "render/ray_traced_shadows.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/raster_pipeline.h"
#include "render/ray_origin_offset.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"
#include "render/shadow_ray_index.h"

#include <cmath>

namespace glint::render {
namespace {

// Image units: the G-buffer and the cube's mask the ray rule reads (include/pixel_shadow_ray.glsl), the
// mask the three-step mask pass writes at kMaskUnit too, and the mask the inline pass writes.
constexpr GLuint kPositionUnit = 1, kNormalUnit = 2, kMaskUnit = 3, kInlineMaskUnit = 4;

std::size_t pixel_count(int width, int height) {
  require_pass_size("shadow rays", width, height);
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

ShadowMethod ray_traced(ShadowMethod method) {
  if (method == ShadowMethod::cube) fail("shadow rays: the cube method casts no shadow rays");
  return method;
}

// The ray rule's uniforms, alike in the program that writes the rays and the one that traces inline.
void set_ray_rule_uniforms(ShaderProgram& program, ShadowMethod method, float origin_offset,
                           float depth_edge_fraction) {
  program.set_uniform("origin_offset", origin_offset);
  program.set_uniform("hybrid", method == ShadowMethod::hybrid ? 1 : 0);
  program.set_uniform("depth_edge_fraction", depth_edge_fraction);
}

void bind_gbuffer_images(const RasterPipeline& raster, GLuint cube_mask) {
  glBindImageTexture(kPositionUnit, raster.world_position(), 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, raster.world_normal_roughness(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     kWorldNormalRoughnessFormat);
  glBindImageTexture(kMaskUnit, cube_mask, 0, GL_FALSE, 0, GL_READ_ONLY, kShadowMaskFormat);
}

}  // namespace

RayTracedShadows::RayTracedShadows(const Scene& scene, int width, int height, ShadowMethod method,
                                   rt::RayTracer& tracer, float origin_offset_fraction, float depth_edge_fraction,
                                   bool gl_inline)
    : method_(ray_traced(method)),
      width_(width),
      height_(height),
      inline_gl_(gl_inline ? tracer.gl_tracing() : nullptr) {
  const std::size_t pixels = pixel_count(width, height);
  const float offset = ray_origin_offset(origin_offset_fraction, scene.world_bounds());
  if (!(offset >= 0.0f) || !std::isfinite(offset))
    fail("shadow rays: origin offset {} must be finite and >= 0", offset);
  if (inline_gl_ != nullptr) {
    inline_program_.emplace(ShaderProgram::from_embedded({"shadow_rays_inline.comp.glsl"}));
    set_ray_rule_uniforms(*inline_program_, method_, offset, depth_edge_fraction);
    if (method_ == ShadowMethod::hybrid) cube_mask_copy_ = create_texture_2d(kShadowMaskFormat, width, height);
  } else {
    buffers_.emplace(pixels, tracer, "shadow rays");
    ray_program_.emplace(ShaderProgram::from_embedded({"shadow_rays.comp.glsl"}));
    mask_program_.emplace(ShaderProgram::from_embedded({"shadow_ray_mask.comp.glsl"}));
    mask_program_->set_uniform("occlusion_flag_bytes", buffers_->flag_bytes());
    set_ray_rule_uniforms(*ray_program_, method_, offset, depth_edge_fraction);
  }
  check_gl("shadow rays: set-up");
}

OcclusionBuffers& RayTracedShadows::steps() {
  if (!buffers_) fail("shadow rays: traced inline by the gl backend, which has no ray list or separate steps");
  return *buffers_;
}

const OcclusionBuffers& RayTracedShadows::steps() const {
  if (!buffers_) fail("shadow rays: traced inline by the gl backend, which has no ray list or separate steps");
  return *buffers_;
}

void RayTracedShadows::run(const RasterPipeline& raster) {
  if (traces_inline()) {
    trace_inline(raster);
    return;
  }
  write_rays(raster);
  trace();
  write_mask(raster);
}

void RayTracedShadows::trace() {
  start_trace();
  finish_trace();
}

void RayTracedShadows::start_trace() {
  OcclusionBuffers& buffers = steps();
  GlPassScope scope("shadow_rays");
  GlPassScope stage("trace");
  buffers.start_trace(buffers.capacity());  // dense: every pixel has a ray, empty or not
}

void RayTracedShadows::write_rays(const RasterPipeline& raster) {
  OcclusionBuffers& buffers = steps();
  if (raster.width() != width_ || raster.height() != height_)
    fail("shadow rays: the raster pipeline is {}x{}, the pass {}x{}", raster.width(), raster.height(), width_, height_);
  GlPassScope scope("shadow_rays");
  GlPassScope stage("ray_generation");
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, raster.frame_constants_buffer());
  buffers.bind();
  bind_gbuffer_images(raster, raster.shadow_mask());
  ray_program_->use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl("shadow rays: generation");
}

void RayTracedShadows::write_mask(const RasterPipeline& raster) {
  OcclusionBuffers& buffers = steps();
  GlPassScope scope("shadow_rays");
  GlPassScope stage("mask");
  buffers.bind();
  glBindImageTexture(kMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kShadowMaskFormat);
  mask_program_->use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("shadow rays: mask");
}

void RayTracedShadows::trace_inline(const RasterPipeline& raster) {
  if (raster.width() != width_ || raster.height() != height_)
    fail("shadow rays: the raster pipeline is {}x{}, the pass {}x{}", raster.width(), raster.height(), width_, height_);
  GlPassScope scope("shadow_rays");
  GlPassScope stage("inline_trace");
  // Hybrid: the rule reads the cube's values of a pixel's neighbours, which their own invocations
  // overwrite in the mask, in no set order; it reads a copy (0.9 MB at 1280x720), as the three steps
  // read the mask before any of it is written. The cube's mask pass ended with a texture-update barrier.
  if (method_ == ShadowMethod::hybrid)
    glCopyImageSubData(raster.shadow_mask(), GL_TEXTURE_2D, 0, 0, 0, 0, cube_mask_copy_.id(), GL_TEXTURE_2D, 0, 0, 0, 0,
                       width_, height_, 1);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, raster.frame_constants_buffer());
  bind_gbuffer_images(raster, method_ == ShadowMethod::hybrid ? cube_mask_copy_.id() : raster.shadow_mask());
  glBindImageTexture(kInlineMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kShadowMaskFormat);
  inline_gl_->bind_inline_tracing(inline_program_->id());
  inline_program_->use();
  // A work group per 8 x 4 block of pixels (its local size).
  const ShadowRayBlock block = shadow_ray_block();
  glDispatchCompute(work_groups(static_cast<std::uint64_t>(width_), static_cast<GLuint>(block.width)),
                    work_groups(static_cast<std::uint64_t>(height_), static_cast<GLuint>(block.height)), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("shadow rays: inline trace");
}

}  // namespace glint::render
