#include "render/visibility_gbuffer_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl/gl_renderer.h"
#include "render/compute_dispatch.h"
#include "render/render_targets.h"


namespace glint::render {
namespace {

// Image units of visibility_gbuffer.comp.glsl (texture unit 0 is the material array, gpu_scene.h).
constexpr GLuint kIdUnit = 0;
constexpr GLuint kAlbedoUnit = 1;
constexpr GLuint kPositionUnit = 2;
constexpr GLuint kNormalUnit = 3;
constexpr GLuint kMaterialIdUnit = 4;
constexpr GLuint kMotionUnit = 5;

// Mesa's software rasterisers: their compute-shader textureGrad is ~60x slower than the whole raster
// G-buffer (docs/render.md, "Visibility G-buffer"), so a shader that filters from texelFetch runs
// there.
bool software_renderer() { return software_gl_renderer(current_gl_renderer()); }

}  // namespace

VisibilityGBufferPass::VisibilityGBufferPass(const RasterTargets& targets, const SurfaceMotion* motion)
    : targets_(&targets),
      motion_(motion),
      program_(ShaderProgram::from_embedded({software_renderer() ? "visibility_gbuffer_texel_fetch.comp.glsl"
                                                                 : "visibility_gbuffer.comp.glsl"})) {
  if (targets.visibility_id.id() == 0) fail("visibility G-buffer pass: the raster targets have no visibility id image");
  check_gl("visibility G-buffer pass set-up");
}

void VisibilityGBufferPass::run(const GpuScene& scene) {
  GlPassScope scope("visibility_gbuffer");
  const RasterTargets& t = *targets_;
  scene.bind_resources();
  glBindImageTexture(kIdUnit, t.visibility_id.id(), 0, GL_FALSE, 0, GL_READ_ONLY, kVisibilityIdFormat);
  glBindImageTexture(kAlbedoUnit, t.albedo_reflectivity.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kAlbedoReflectivityFormat);
  glBindImageTexture(kPositionUnit, t.world_position.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, t.world_normal_roughness.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                     kWorldNormalRoughnessFormat);
  glBindImageTexture(kMaterialIdUnit, t.material_id.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kMaterialIdFormat);
  program_.set_uniform("write_motion", motion_ != nullptr ? 1 : 0);
  if (motion_ != nullptr) {
    glBindImageTexture(kMotionUnit, motion_->world_motion(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kWorldMotionFormat);
    motion_->bind_previous_vertices();
  }
  program_.use();
  dispatch_over_image(t.width, t.height);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("visibility G-buffer pass");
}

}  // namespace glint::render
