#pragma once
// The raster half of the deferred renderer: G-buffer (rasterised, or a visibility buffer resolved by
// a compute pass: RasterSettings::gbuffer), shadow (cube map + mask), direct lighting.
// Owns the GpuScene, the full-screen targets, the FrameConstants uniform buffer and the passes.
// SSR, the ray-traced complement and resolve read the targets by texture id afterwards; the
// FrameConstants UBO stays bound at kFrameConstantsBinding after render().
//
//   RasterPipeline raster(scene, 1280, 720, settings);
//   raster.render(animation.at(frame), &timer);   // "gbuffer", "shadow", "light" in the timer
//   ssr.run(raster.world_position(), ...);
#include "core/image.h"
#include "gl/gl_objects.h"
#include "gl/gpu_timer.h"
#include "render/compute_visibility_pass.h"
#include "render/frame_constants.h"
#include "render/gbuffer_pass.h"
#include "render/gpu_scene.h"
#include "render/lighting_pass.h"
#include "render/primary_ray_pass.h"
#include "render/primary_visibility_choice.h"
#include "render/raster_settings.h"
#include "render/raster_targets.h"
#include "render/scene_world_bounds.h"
#include "render/shadow_chunks.h"
#include "render/shadow_cube_pass.h"
#include "render/shadow_mask_pass.h"
#include "render/visibility_gbuffer_pass.h"
#include "render/surface_motion.h"
#include "render/visibility_id_pass.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <functional>
#include <optional>

namespace glint::render {

// Every image the pipeline writes, for readback and debug views.
enum class RasterOutput { AlbedoReflectivity, WorldPosition, WorldNormalRoughness, MaterialId, Depth, ShadowMask, Lit };

// How RasterPipeline::render makes the shadow mask (ShadowMethod): the cube map and its PCF mask
// (cube, and hybrid's first half), then `after_cube` (the shadow rays of rt and hybrid:
// RayTracedShadows), both inside the "shadow" timing.
struct RasterShadowSteps {
  bool cube = true;
  std::function<void()> after_cube;
};

class RasterPipeline {
public:
  // Uploads `scene`, which must outlive the pipeline (each frame reads its light, sky and bounds;
  // deforming callers update it and gpu_scene() together). Needs a current GL context.
  RasterPipeline(const Scene& scene, int width, int height, const RasterSettings& settings = {});

  // G-buffer, then shadow (cube map + mask, which needs this frame's G-buffer), then lighting. With
  // a timer (inside its begin_frame/end_frame) the passes are timed as "gbuffer" (with the
  // visibility method: the id draw and the compute resolve together), "shadow", "light".
  void render(const FrameState& frame, GpuTimer* timer = nullptr, const RasterShadowSteps& shadow = {});
  // render() in two halves, for FramePipeline, which traces its rays between them (docs/render.md
  // "One hand-over a frame"): the G-buffer and the shadow steps, then lighting (which reads the
  // shadow mask, so whatever finishes the mask goes between).
  void render_surfaces(const FrameState& frame, GpuTimer* timer, const RasterShadowSteps& shadow);
  void light(GpuTimer* timer);

  // PrimaryVisibility::rt: the tracer whose camera rays make the visibility ids (PrimaryRayPass);
  // it must be built over the scene and outlive the pipeline. Must be called before the first
  // render() with rt (glint::Error there otherwise); glint::Error with PrimaryVisibility::raster.
  void trace_primary_visibility(rt::RayTracer& tracer);
  // The primary rays (PrimaryVisibility::rt after trace_primary_visibility), for tests; else null.
  const PrimaryRayPass* primary_rays() const { return primary_rays_ ? &*primary_rays_ : nullptr; }
  // The method that makes the ids: RasterSettings::primary, or, for automatic, the one the first
  // frame chose (automatic until then). Meaningless with the raster G-buffer, which makes no ids.
  PrimaryVisibility primary_visibility() const;
  // PrimaryVisibility::automatic with the visibility G-buffer, after the first frame: both methods'
  // times and the choice (run.json records them); else nullopt.
  const std::optional<PrimaryVisibilityChoice>& primary_visibility_choice() const { return primary_choice_; }
  // The compute rasteriser (PrimaryVisibility::compute, or automatic until the first frame chose the
  // id draw), for tests; else null.
  const ComputeVisibilityPass* compute_visibility() const { return compute_visibility_ ? &*compute_visibility_ : nullptr; }

  GLuint albedo_reflectivity() const { return targets_.albedo_reflectivity.id(); }
  GLuint world_position() const { return targets_.world_position.id(); }
  GLuint world_normal_roughness() const { return targets_.world_normal_roughness.id(); }
  GLuint material_id() const { return targets_.material_id.id(); }
  GLuint depth() const { return targets_.depth.id(); }
  GLuint shadow_mask() const { return targets_.shadow_mask.id(); }
  GLuint lit() const { return targets_.lit.id(); }
  GLuint visibility_id() const { return targets_.visibility_id.id(); }  // 0 unless the visibility method
  // SurfaceMotion's world motion image (RasterSettings::surface_motion); 0 when off.
  GLuint world_motion() const { return surface_motion_ ? surface_motion_->world_motion() : 0; }
  GLuint shadow_cube_map() const { return shadow_cube_.cube_map(); }
  const ShadowCubePass& shadow_cube() const { return shadow_cube_; }  // size and far distance too
  GLuint frame_constants_buffer() const { return frame_constants_buffer_.id(); }
  const FrameConstants& frame_constants() const { return frame_constants_; }  // of the last render()
  GpuScene& gpu_scene() { return gpu_scene_; }
  const GpuScene& gpu_scene() const { return gpu_scene_; }
  const RasterSettings& settings() const { return settings_; }
  int width() const { return targets_.width; }
  int height() const { return targets_.height; }

  // CPU copies of an output, top row first; see read_texture_rgbaf for one-channel images. They
  // wait for the GPU: debug views and tests only. rgba8 clamps to 0..1 (no tone mapping).
  ImageRgbaF read_rgbaf(RasterOutput output) const;
  ImageRgba8 read_rgba8(RasterOutput output) const;

private:
  // PrimaryVisibility::automatic's first frame: times both id makers and keeps the faster.
  void choose_primary_visibility();

  const Scene* scene_;
  RasterSettings settings_;
  GpuScene gpu_scene_;
  RasterTargets targets_;
  GlBuffer frame_constants_buffer_;
  FrameConstants frame_constants_;
  SceneWorldBounds world_bounds_;
  std::optional<SurfaceMotion> surface_motion_;  // RasterSettings::surface_motion; both G-buffer methods write it
  // One G-buffer method is made, the one RasterSettings::gbuffer names.
  std::optional<GBufferPass> gbuffer_;
  std::optional<VisibilityIdPass> visibility_ids_;
  std::optional<VisibilityGBufferPass> visibility_gbuffer_;
  std::optional<PrimaryRayPass> primary_rays_;  // PrimaryVisibility::rt instead of visibility_ids_
  std::optional<ComputeVisibilityPass> compute_visibility_;  // PrimaryVisibility::compute instead of visibility_ids_
  // PrimaryVisibility::automatic: both of the above until the first frame, which times them here.
  std::optional<PrimaryVisibilityChoice> primary_choice_;
  ShadowCubePass shadow_cube_;
  ShadowMaskPass shadow_mask_;
  LightingPass lighting_;
  // The scene in pieces for the per-face shadow draw's culling, made at load time; not made for
  // the layered draw, which does not use them.
  std::optional<ShadowChunks> shadow_chunks_;
};

}  // namespace glint::render
