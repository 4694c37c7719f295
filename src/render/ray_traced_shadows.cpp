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

#include <cmath>

namespace glint::render {
namespace {

constexpr GLuint kPositionUnit = 1, kNormalUnit = 2, kMaskUnit = 3;  // image units of both shaders

std::size_t pixel_count(int width, int height) {
  require_pass_size("shadow rays", width, height);
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

ShadowMethod ray_traced(ShadowMethod method) {
  if (method == ShadowMethod::cube) fail("shadow rays: the cube method casts no shadow rays");
  return method;
}

}  // namespace

RayTracedShadows::RayTracedShadows(const Scene& scene, int width, int height, ShadowMethod method,
                                   rt::RayTracer& tracer, float origin_offset_fraction, float depth_edge_fraction)
    : method_(ray_traced(method)),
      width_(width),
      height_(height),
      buffers_(pixel_count(width, height), tracer, "shadow rays"),
      ray_program_(ShaderProgram::from_embedded({"shadow_rays.comp.glsl"})),
      mask_program_(ShaderProgram::from_embedded({"shadow_ray_mask.comp.glsl"})) {
  mask_program_.set_uniform("occlusion_flag_bytes", buffers_.flag_bytes());
  const float offset = ray_origin_offset(origin_offset_fraction, scene.world_bounds());
  if (!(offset >= 0.0f) || !std::isfinite(offset))
    fail("shadow rays: origin offset {} must be finite and >= 0", offset);
  ray_program_.set_uniform("origin_offset", offset);
  ray_program_.set_uniform("hybrid", method_ == ShadowMethod::hybrid ? 1 : 0);
  ray_program_.set_uniform("depth_edge_fraction", depth_edge_fraction);
  check_gl("shadow rays: set-up");
}

void RayTracedShadows::run(const RasterPipeline& raster) {
  write_rays(raster);
  trace();
  write_mask(raster);
}

void RayTracedShadows::trace() {
  start_trace();
  finish_trace();
}

void RayTracedShadows::start_trace() {
  GlPassScope scope("shadow_rays");
  GlPassScope stage("trace");
  buffers_.start_trace(buffers_.capacity());  // dense: every pixel has a ray, empty or not
}

void RayTracedShadows::write_rays(const RasterPipeline& raster) {
  if (raster.width() != width_ || raster.height() != height_)
    fail("shadow rays: the raster pipeline is {}x{}, the pass {}x{}", raster.width(), raster.height(), width_, height_);
  GlPassScope scope("shadow_rays");
  GlPassScope stage("ray_generation");
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, raster.frame_constants_buffer());
  buffers_.bind();
  glBindImageTexture(kPositionUnit, raster.world_position(), 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, raster.world_normal_roughness(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     kWorldNormalRoughnessFormat);
  glBindImageTexture(kMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_READ_ONLY, kShadowMaskFormat);
  ray_program_.use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl("shadow rays: generation");
}

void RayTracedShadows::write_mask(const RasterPipeline& raster) {
  GlPassScope scope("shadow_rays");
  GlPassScope stage("mask");
  buffers_.bind();
  glBindImageTexture(kMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kShadowMaskFormat);
  mask_program_.use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("shadow rays: mask");
}

}  // namespace glint::render
