#include "render/raster_pipeline.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_renderer.h"
#include "render/render_targets.h"
#include "render/texture_readback.h"

#include <optional>

namespace glint::render {
namespace {

const RasterSettings& validated(const RasterSettings& settings) {
  settings.validate();
  return settings;
}

GpuSceneOptions gpu_scene_options(const RasterSettings& settings) {
  GpuSceneOptions options;
  options.max_texture_layer_size = settings.max_texture_layer_size;
  return options;
}

}  // namespace

RasterPipeline::RasterPipeline(const Scene& scene, int width, int height, const RasterSettings& settings)
    : scene_(&scene),
      settings_(validated(settings)),
      gpu_scene_(scene, gpu_scene_options(settings)),
      targets_(width, height, settings_.gbuffer == GBufferMethod::visibility),
      frame_constants_buffer_(create_buffer(sizeof(FrameConstants), nullptr, GL_DYNAMIC_STORAGE_BIT)),
      shadow_cube_(settings.shadow_map_size, settings.shadow_cube_draw),
      shadow_mask_(targets_),
      lighting_(targets_),
      shadow_chunks_(settings_.shadow_cube_draw == ShadowCubeDraw::per_face
                         ? std::optional<ShadowChunks>(std::in_place, scene, gpu_scene_)
                         : std::nullopt) {
  if (settings_.surface_motion) surface_motion_.emplace(scene, gpu_scene_, width, height);
  const SurfaceMotion* motion = surface_motion_ ? &*surface_motion_ : nullptr;
  if (settings_.gbuffer == GBufferMethod::visibility) {
    // automatic: a software renderer keeps the id draw untimed; elsewhere both are made and the first
    // frame times them and drops the slower (primary_visibility_choice.h).
    if (settings_.primary == PrimaryVisibility::automatic)
      primary_choice_ = untimed_primary_visibility(current_gl_renderer());
    const PrimaryVisibility primary = primary_visibility();
    if (primary == PrimaryVisibility::raster || primary == PrimaryVisibility::automatic) visibility_ids_.emplace(targets_);
    if (primary == PrimaryVisibility::compute || primary == PrimaryVisibility::automatic)
      compute_visibility_.emplace(targets_, gpu_scene_);
    visibility_gbuffer_.emplace(targets_, motion);
  } else {
    gbuffer_.emplace(targets_, motion);
  }
  check_gl("raster pipeline set-up");
}

void RasterPipeline::render(const FrameState& frame, GpuTimer* timer, const RasterShadowSteps& shadow) {
  render_surfaces(frame, timer, shadow);
  light(timer);
}

void RasterPipeline::render_surfaces(const FrameState& frame, GpuTimer* timer, const RasterShadowSteps& shadow) {
  // The scene's bounds (deforming meshes move them): once per frame, for both the camera's clip range
  // and the shadow cube's near distance; only the meshes that can have changed are scanned again.
  const Aabb world_bounds = world_bounds_.of(*scene_, gpu_scene_);
  frame_constants_ = make_frame_constants(*scene_, world_bounds, frame, targets_.width, targets_.height);
  glNamedBufferSubData(frame_constants_buffer_.id(), 0, sizeof(FrameConstants), &frame_constants_);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, frame_constants_buffer_.id());

  // Before the first frame's "gbuffer" timing opens: the choice is a one-off cost, not the frame's.
  if (visibility_ids_ && compute_visibility_) choose_primary_visibility();

  // A pass is timed only when there is a timer (PassScope cannot move, so it is emplaced in place).
  std::optional<GpuTimer::PassScope> timed;
  if (timer != nullptr) timed.emplace(*timer, "gbuffer");
  if (gbuffer_) {
    gbuffer_->run(gpu_scene_);
  } else {
    if (primary_rays_)
      primary_rays_->run();
    else if (visibility_ids_)
      visibility_ids_->run(gpu_scene_);
    else if (compute_visibility_)
      compute_visibility_->run();
    else
      fail("raster pipeline: ray-traced primary visibility without a ray tracer (trace_primary_visibility)");
    visibility_gbuffer_->run(gpu_scene_);
  }
  if (surface_motion_) surface_motion_->keep_vertices(gpu_scene_);  // the next frame's previous vertices
  timed.reset();
  if (timer != nullptr) timed.emplace(*timer, "shadow");
  if (shadow.cube) {
    shadow_cube_.run(gpu_scene_, frame.light_position, world_bounds, shadow_chunks_ ? &*shadow_chunks_ : nullptr);
    shadow_mask_.run(shadow_cube_, settings_);
  }
  if (shadow.after_cube) shadow.after_cube();
}

void RasterPipeline::choose_primary_visibility() {
  primary_choice_ = render::choose_primary_visibility([&] { visibility_ids_->run(gpu_scene_); },
                                                      [&] { compute_visibility_->run(); });
  if (primary_choice_->method == PrimaryVisibility::compute)
    visibility_ids_.reset();
  else
    compute_visibility_.reset();
}

PrimaryVisibility RasterPipeline::primary_visibility() const {
  if (settings_.primary != PrimaryVisibility::automatic) return settings_.primary;
  return primary_choice_ ? primary_choice_->method : PrimaryVisibility::automatic;
}

void RasterPipeline::light(GpuTimer* timer) {
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, frame_constants_buffer_.id());
  run_timed_pass(timer, "light", [&] { lighting_.run(gpu_scene_, settings_); });
}

void RasterPipeline::trace_primary_visibility(rt::RayTracer& tracer) {
  if (settings_.primary != PrimaryVisibility::rt)
    fail("raster pipeline: a primary-ray tracer given with primary visibility '{}'",
         primary_visibility_name(settings_.primary));
  primary_rays_.emplace(targets_, tracer);
}

ImageRgbaF RasterPipeline::read_rgbaf(RasterOutput output) const {
  const int w = targets_.width, h = targets_.height;
  switch (output) {
    case RasterOutput::AlbedoReflectivity: return read_texture_rgbaf(albedo_reflectivity(), kAlbedoReflectivityFormat, w, h);
    case RasterOutput::WorldPosition: return read_texture_rgbaf(world_position(), kWorldPositionFormat, w, h);
    case RasterOutput::WorldNormalRoughness:
      return read_texture_rgbaf(world_normal_roughness(), kWorldNormalRoughnessFormat, w, h);
    case RasterOutput::MaterialId: return read_texture_rgbaf(material_id(), kMaterialIdFormat, w, h);
    case RasterOutput::Depth:
      if (compute_visibility_) {  // the compute raster writes it on demand
        glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, frame_constants_buffer_.id());
        compute_visibility_->write_depth();
      }
      return read_texture_rgbaf(depth(), kDepthFormat, w, h);
    case RasterOutput::ShadowMask: return read_texture_rgbaf(shadow_mask(), kShadowMaskFormat, w, h);
    case RasterOutput::Lit: return read_texture_rgbaf(lit(), kLitFormat, w, h);
  }
  fail("raster pipeline: unknown output {}", static_cast<int>(output));
}

ImageRgba8 RasterPipeline::read_rgba8(RasterOutput output) const { return quantize_to_rgba8(read_rgbaf(output)); }

}  // namespace glint::render
