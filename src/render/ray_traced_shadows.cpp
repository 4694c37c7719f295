#include "render/ray_traced_shadows.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/persistent_buffer.h"
#include "render/raster_pipeline.h"
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
      tracer_(&tracer),
      device_(tracer.device_tracing()),
      width_(width),
      height_(height),
      pixels_(pixel_count(width, height)),
      ray_program_(ShaderProgram::from_embedded({"shadow_rays.comp.glsl"})),
      mask_program_(ShaderProgram::from_embedded({"shadow_ray_mask.comp.glsl"})) {
  const auto count = static_cast<std::uint32_t>(pixels_);
  ray_count_ = create_buffer(sizeof(count), &count, 0);
  if (device_) {
    rays_ = create_buffer(pixels_ * sizeof(accel::Ray), nullptr, 0);
    occluded_ = create_buffer(pixels_ * sizeof(std::uint32_t), nullptr, 0);  // trace_any_device: a uint per ray
    const cuda::InteropBuffer shared[] = {{rays_.id(), cuda::InteropAccess::read_only},
                                          {occluded_.id(), cuda::InteropAccess::write_discard},
                                          {ray_count_.id(), cuda::InteropAccess::read_only}};
    interop_.emplace(shared);
    mask_program_.set_uniform("flag_bytes", 4);
  } else {
    void* mapped = nullptr;
    rays_ = create_persistently_mapped_buffer(pixels_ * sizeof(accel::Ray), GL_MAP_READ_BIT, &mapped, "shadow rays");
    mapped_rays_ = static_cast<accel::Ray*>(mapped);
    // trace_any writes a byte per ray; the shader reads whole uints, so the size is rounded up.
    occluded_ = create_persistently_mapped_buffer((pixels_ + 3) / 4 * 4, GL_MAP_WRITE_BIT, &mapped,
                                                  "shadow ray answers");
    mapped_occluded_ = static_cast<std::uint8_t*>(mapped);
    ray_fence_.emplace(1, sizeof(count), "shadow rays");
    mask_program_.set_uniform("flag_bytes", 1);
  }
  const float diagonal = length(scene.world_bounds().extent());
  const float offset = origin_offset_fraction * (diagonal > 0.0f ? diagonal : 1.0f);
  if (!(offset >= 0.0f) || !std::isfinite(offset))
    fail("shadow rays: origin offset {} must be finite and >= 0", offset);
  ray_program_.set_uniform("origin_offset", offset);
  ray_program_.set_uniform("hybrid", method_ == ShadowMethod::hybrid ? 1 : 0);
  ray_program_.set_uniform("depth_edge_fraction", depth_edge_fraction);
  check_gl("shadow rays: set-up");
}

void RayTracedShadows::run(const RasterPipeline& raster) {
  GlPassScope scope("shadow_rays");
  if (raster.width() != width_ || raster.height() != height_)
    fail("shadow rays: the raster pipeline is {}x{}, the pass {}x{}", raster.width(), raster.height(), width_, height_);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, raster.frame_constants_buffer());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowRayBinding, rays_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowOcclusionBinding, occluded_.id());
  glBindImageTexture(kPositionUnit, raster.world_position(), 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, raster.world_normal_roughness(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     kWorldNormalRoughnessFormat);
  glBindImageTexture(kMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_READ_ONLY, kShadowMaskFormat);
  ray_program_.use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  const auto count = static_cast<std::uint32_t>(pixels_);
  if (device_) {
    // Mapping orders the CUDA stream after the ray pass, unmapping orders the mask pass after the
    // trace: the host only enqueues.
    cuda::ScopedInteropMap mapped(*interop_, device_->stream());
    device_->trace_any_device(mapped.pointer<const accel::Ray>(0), mapped.pointer<std::uint32_t>(1),
                              mapped.pointer<const std::uint32_t>(2), count);
  } else {
    // The fence behind a 4-byte copy also makes the rays reach the coherent mapping (the ring's
    // barrier); the answers written by the CPU reach GL commands issued after them (coherent).
    ray_fence_->copy_buffer(0, ray_count_.id(), sizeof(count));
    (void)ray_fence_->read(0, /*wait=*/true);
    tracer_->trace_any({mapped_rays_, pixels_}, {mapped_occluded_, pixels_});
  }

  glBindImageTexture(kMaskUnit, raster.shadow_mask(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kShadowMaskFormat);
  mask_program_.use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("shadow rays");
}

std::span<const accel::Ray> RayTracedShadows::rays() const {
  if (mapped_rays_ == nullptr) fail("shadow rays: the rays of a GPU backend stay in GPU memory");
  return {mapped_rays_, pixels_};
}

std::span<const std::uint8_t> RayTracedShadows::occluded() const {
  if (mapped_occluded_ == nullptr) fail("shadow rays: the answers of a GPU backend stay in GPU memory");
  return {mapped_occluded_, pixels_};
}

}  // namespace glint::render
