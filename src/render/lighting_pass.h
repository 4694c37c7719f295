#pragma once
// LightingPass: direct lighting of the G-buffer (Blinn-Phong point light x shadow mask, ambient,
// emissive; sky colour on background). Full screen; the formula is in shaders/lighting.frag.glsl.
//   inputs:  RasterTargets albedo_reflectivity, world_position, world_normal_roughness, material_id,
//            shadow_mask; GpuScene materials; FrameConstants UBO at kFrameConstantsBinding
//   outputs: RasterTargets lit (kLitFormat, linear HDR radiance, a = 1)
#include "render/fullscreen_draw.h"
#include "render/gpu_scene.h"
#include "render/raster_settings.h"
#include "render/raster_targets.h"

namespace glint::render {

class LightingPass {
public:
  explicit LightingPass(const RasterTargets& targets);  // the targets must outlive the pass

  void run(const GpuScene& scene, const RasterSettings& settings);

private:
  const RasterTargets* targets_;
  FullscreenDraw draw_;
};

}  // namespace glint::render
