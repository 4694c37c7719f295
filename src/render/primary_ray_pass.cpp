#include "render/primary_ray_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

constexpr GLuint kIdUnit = 0;  // image unit of primary_ids.comp.glsl

std::size_t pixel_count(const RasterTargets& targets) {
  require_pass_size("primary rays", targets.width, targets.height);
  if (targets.visibility_id.id() == 0) fail("primary rays: the raster targets have no visibility id image");
  return static_cast<std::size_t>(targets.width) * static_cast<std::size_t>(targets.height);
}

}  // namespace

PrimaryRayPass::PrimaryRayPass(const RasterTargets& targets, rt::RayTracer& tracer)
    : targets_(&targets),
      buffers_(pixel_count(targets), tracer, "primary rays", RayQuery::closest),
      ray_program_(ShaderProgram::from_embedded({"primary_rays.comp.glsl"})),
      id_program_(ShaderProgram::from_embedded({"primary_ids.comp.glsl"})) {
  check_gl("primary rays: set-up");
}

void PrimaryRayPass::run() {
  GlPassScope scope("primary_rays");
  const RasterTargets& t = *targets_;
  buffers_.bind();
  ray_program_.use();
  { GlPassScope stage("ray_generation"); dispatch_over_image(t.width, t.height); }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

  { GlPassScope stage("trace"); buffers_.trace(buffers_.capacity()); }  // dense: every pixel has a ray

  glBindImageTexture(kIdUnit, t.visibility_id.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kVisibilityIdFormat);
  id_program_.use();
  { GlPassScope stage("ids"); dispatch_over_image(t.width, t.height); }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  check_gl("primary rays");
}

}  // namespace glint::render
