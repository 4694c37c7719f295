#pragma once
// HitShadingPass: the last step of the ray-traced complement. One compute invocation per listed ray
// shades its hit record {t, instance, prim, u, v} from the GpuScene buffers alone, with the
// materials, textures and lighting of the raster path (shaders/include/surface_lighting.glsl) and
// the shadow of the light's cube map (shaders/include/cube_shadow.glsl, valid at any world
// position; with rt and hybrid shadows, the answer of a shadow ray from the hit: HitShadowRays),
// and stores vec4(radiance, reflected distance) at the ray's pixel of the reflection
// image, in the format SSR writes (kReflectionFormat), so both go through the same resolve.
// A miss stores the sky colour at kMissDistance: the sky is infinitely far, so the distance fade
// removes it unless the fade is off.
//   inputs:  RayHitBuffers (rays, pixels, hits), GpuScene, shadow cube, FrameConstants UBO
//   outputs: the given reflection image, at the listed pixels only
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/occlusion_buffers.h"
#include "render/ray_hit_buffers.h"
#include "render/raster_settings.h"
#include "render/shadow_cube_pass.h"

#include <epoxy/gl.h>

#include <cstdint>

namespace glint::render {

// The distance stored for a ray that hit nothing (the largest round number a half float holds).
inline constexpr float kMissDistance = 60000.0f;

struct HitShadingInputs {
  const GpuScene* scene = nullptr;
  const ShadowCubePass* shadow_cube = nullptr;  // the light's cube map of this frame
  const RasterSettings* raster = nullptr;       // shadow bias, PCF and ambient, as the raster path used
  GLuint frame_constants = 0;                   // uniform buffer holding FrameConstants
  GLuint reflection = 0;                        // target: kReflectionFormat, width x height
  // With rt and hybrid shadows: the answers of the shadow rays cast from the hits (HitShadowRays),
  // slot i for ray i, used instead of the cube map; null: the cube map.
  const OcclusionBuffers* shadow_answers = nullptr;
  // The G-buffer's world_normal_roughness (kWorldNormalRoughnessFormat): the reflecting pixels'
  // normal and roughness, for the BRDF weight of glossy rays (docs/glossy.md); 0: every weight 1.
  GLuint world_normal_roughness = 0;
};

class HitShadingPass {
public:
  // Compiles the shader; throws glint::Error for a non-positive size.
  HitShadingPass(int width, int height, RayHitBuffers& buffers);

  // Shades the rays of the list (their hits written by the tracer) into inputs.reflection. The
  // shader reads the list's length from the counter buffer; the dispatch covers `max_rays` (the
  // count when the host knows it, else the capacity). Inputs are checked (glint::Error naming the
  // input). Ends with a barrier that makes the reflection image visible to later image loads,
  // fetches and readbacks.
  void run(const HitShadingInputs& inputs, std::uint32_t max_rays);

private:
  ShaderProgram program_;
  RayHitBuffers* buffers_;
  int width_, height_;
};

}  // namespace glint::render
