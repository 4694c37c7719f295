#pragma once
// LightingPass: direct lighting of the G-buffer (Blinn-Phong point light x shadow mask, ambient,
// emissive; sky colour on background). A compute pass, one invocation per pixel (fragment work runs on a few SMs of some GPUs: 4 of 132
// on an H100); the formula is in shaders/lighting.comp.glsl.
//   inputs:  RasterTargets albedo_reflectivity, world_position, world_normal_roughness, material_id,
//            shadow_mask; GpuScene materials; FrameConstants UBO at kFrameConstantsBinding
//   outputs: RasterTargets lit (kLitFormat, linear HDR radiance, a = 1)
#include "gl/shader_program.h"
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
  ShaderProgram program_;
};

}  // namespace glint::render
