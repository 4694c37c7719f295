#include "render/reflection_denoiser.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"
#include "render/surface_motion.h"

#include <cstddef>
#include <string>

namespace glint::render {
namespace {

constexpr GLenum kHistoryFormat = GL_RGBA16F;
constexpr GLenum kGuideFormat = GL_RG32UI;  // include/denoiser_guide.glsl
constexpr GLuint kMotionBinding = 24;  // storage binding of the motion buffer (reflection_temporal.comp.glsl)
// Between the passes of one run: the next pass fetches (texelFetch) what the last one stored.
constexpr GLbitfield kBetweenPasses = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT;

// The guide's camera rays (include/denoiser_guide.glsl's GuideRays) of view-projection `vp` over a
// width x height image: the projection centre and the affine map of pixel centres to the directions
// towards the far plane, from the inverse in double precision. A perspective view-projection maps
// the eye to (0, 0, z, 0), and the far plane's points have one w, so the map is exact.
struct GuideRays {
  vec3 origin, corner, step_x, step_y;
};

GuideRays guide_rays(const mat4& vp, int width, int height) {
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(vp));
  const glm::dvec4 eye = inverse * glm::dvec4(0.0, 0.0, 1.0, 0.0);
  const glm::dvec3 origin = glm::dvec3(eye) / eye.w;
  const auto direction = [&](double x, double y) {
    const glm::dvec4 far_point = inverse * glm::dvec4(x, y, 1.0, 1.0);
    return glm::dvec3(far_point) / far_point.w - origin;
  };
  const glm::dvec3 corner = direction(-1.0, -1.0);
  return {vec3(origin), vec3(corner), vec3((direction(1.0, -1.0) - corner) / static_cast<double>(width)),
          vec3((direction(-1.0, 1.0) - corner) / static_cast<double>(height))};
}

void set_rays(ShaderProgram& program, const std::string& name, const GuideRays& rays) {
  program.set_uniform(name + ".origin", rays.origin);
  program.set_uniform(name + ".corner", rays.corner);
  program.set_uniform(name + ".step_x", rays.step_x);
  program.set_uniform(name + ".step_y", rays.step_y);
}

}  // namespace

ReflectionDenoiser::ReflectionDenoiser(int width, int height)
    : temporal_(ShaderProgram::from_embedded({"reflection_temporal.comp.glsl"})),
      spatial_(ShaderProgram::from_embedded({"reflection_spatial.comp.glsl"})),
      width_(width),
      height_(height) {
  require_pass_size("reflection denoiser", width, height);
  for (int i = 0; i < 2; ++i) {
    history_[i] = create_texture_2d(kHistoryFormat, width, height);
    filtered_[i] = create_texture_2d(kHistoryFormat, width, height);
    guide_[i] = create_texture_2d(kGuideFormat, width, height);
    // An integer texture with a filtering (the default) minification filter is incomplete: fetches give 0.
    glTextureParameteri(guide_[i].id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(guide_[i].id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  check_gl("reflection denoiser: set-up");
}

void ReflectionDenoiser::record_motion(bool on) {
  if (on && motion_.id() == 0)
    motion_ = create_buffer(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * sizeof(vec2),
                            nullptr, GL_DYNAMIC_STORAGE_BIT);
  if (!on) motion_ = GlBuffer();
  check_gl("reflection denoiser: motion buffer");
}

void ReflectionDenoiser::run(const DenoiserInputs& inputs, const ResolveSettings& settings) {
  GlPassScope scope("denoise");
  const int w = width_, h = height_;
  require_texture("reflection denoiser", "reflection", inputs.reflection, kReflectionFormat, w, h);
  require_texture("reflection denoiser", "world_position", inputs.world_position, kWorldPositionFormat, w, h);
  require_texture("reflection denoiser", "world_normal_roughness", inputs.world_normal_roughness,
                  kWorldNormalRoughnessFormat, w, h);
  require_texture("reflection denoiser", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat,
                  w, h);
  require_buffer("reflection denoiser", "frame_constants", inputs.frame_constants);
  if (inputs.world_motion != 0)
    require_texture("reflection denoiser", "world_motion", inputs.world_motion, kWorldMotionFormat, w, h);
  const DenoiseSettings& d = settings.denoiser;
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);

  // Temporal: history_[current_ ^ 1] (last frame's) -> history_[current_]; this frame's guide into
  // guide_[current_], last frame's read from guide_[current_ ^ 1].
  temporal_.set_uniform("previous_view_projection", previous_view_projection_);
  const GuideRays rays = guide_rays(inputs.view_projection, w, h);
  set_rays(temporal_, "rays", rays);
  set_rays(temporal_, "previous_rays", guide_rays(previous_view_projection_, w, h));
  temporal_.set_uniform("has_history", has_history_ ? 1 : 0);
  temporal_.set_uniform("has_motion", inputs.world_motion != 0 ? 1 : 0);
  temporal_.set_uniform("record_motion", motion_.id() != 0 ? 1 : 0);
  temporal_.set_uniform("max_history", d.max_history);
  temporal_.set_uniform("clamp_sigma", d.clamp_sigma);
  temporal_.set_uniform("depth_tolerance", d.depth_tolerance);
  temporal_.set_uniform("fade_start", settings.fade_start);
  temporal_.set_uniform("fade_end", settings.fade_end);
  glBindTextureUnit(0, inputs.reflection);
  glBindTextureUnit(1, inputs.world_position);
  glBindTextureUnit(2, inputs.world_normal_roughness);
  glBindTextureUnit(3, inputs.albedo_reflectivity);
  glBindTextureUnit(4, history_[current_ ^ 1].id());
  glBindTextureUnit(5, guide_[current_ ^ 1].id());
  glBindTextureUnit(6, inputs.world_motion);
  glBindImageTexture(0, history_[current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kHistoryFormat);
  glBindImageTexture(1, guide_[current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kGuideFormat);
  if (motion_.id() != 0) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMotionBinding, motion_.id());
  motion_recorded_ = motion_.id() != 0;
  temporal_.use();
  dispatch_over_image(w, h);
  glMemoryBarrier(kBetweenPasses);

  // Spatial: a-trous iterations, ping-pong through filtered_.
  spatial_.set_uniform("max_sigma", d.max_sigma);
  spatial_.set_uniform("depth_sigma", d.depth_sigma);
  spatial_.set_uniform("normal_power", d.normal_power);
  spatial_.set_uniform("roughness_sigma", d.roughness_sigma);
  set_rays(spatial_, "rays", rays);
  glBindTextureUnit(1, guide_[current_].id());
  glBindTextureUnit(2, inputs.world_normal_roughness);
  GLuint source = history_[current_].id();
  for (int i = 0; i < d.iterations; ++i) {
    const int target = i % 2;
    spatial_.set_uniform("step", 1 << i);
    spatial_.set_uniform("last_iteration", i + 1 == d.iterations ? 1 : 0);
    glBindTextureUnit(0, source);
    glBindImageTexture(0, filtered_[target].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kHistoryFormat);
    spatial_.use();
    dispatch_over_image(w, h);
    glMemoryBarrier(kBetweenPasses);
    source = filtered_[target].id();
    last_output_ = target;
  }
  // Later readers: the resolve's image loads, readbacks of the outputs.
  glMemoryBarrier(kBetweenPasses | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);

  // This frame becomes the next one's history.
  previous_view_projection_ = inputs.view_projection;
  has_history_ = true;
  current_ ^= 1;
  for (GLuint unit = 0; unit < 7; ++unit) glBindTextureUnit(unit, 0);
  check_gl("reflection denoiser");
}

std::vector<vec2> ReflectionDenoiser::read_motion() const {
  if (!motion_recorded_) fail("reflection denoiser: read_motion() without record_motion(true) before the run");
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<vec2> motion(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  glGetNamedBufferSubData(motion_.id(), 0, static_cast<GLsizeiptr>(motion.size() * sizeof(vec2)), motion.data());
  check_gl("reflection denoiser: motion readback");
  return motion;
}

}  // namespace glint::render
