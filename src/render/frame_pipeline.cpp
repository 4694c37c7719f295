#include "render/frame_pipeline.h"

#include "gl/gl_check.h"
#include "render/debug_views.h"
#include "render/render_targets.h"
#include "render/texture_readback.h"

namespace glint::render {
namespace {

// Runs `work` as a timed pass when there is a timer.
template <typename Work>
void timed(GpuTimer* timer, std::string_view name, Work&& work) {
  if (timer == nullptr) {
    work();
    return;
  }
  auto scope = timer->time_pass(name);
  work();
}

GlTexture make_cleared_reflection(int width, int height) {
  GlTexture texture = create_texture_2d(kReflectionFormat, width, height);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(texture.id(), 0, GL_RGBA, GL_FLOAT, zero);
  check_gl("clearing the empty reflection image");
  return texture;
}

const FramePipelineSettings& validated(const FramePipelineSettings& settings) {
  settings.validate();
  return settings;
}

}  // namespace

void FramePipelineSettings::validate() const {
  raster.validate();
  render::validate(ssr);
  render::validate(resolve);
}

FramePipeline::FramePipeline(const Scene& scene, int width, int height, const FramePipelineSettings& settings)
    : scene_(&scene),
      settings_(validated(settings)),
      raster_(scene, width, height, settings.raster),
      resolve_(width, height, settings.resolve) {
  if (settings_.reflections == ReflectionMode::off)
    no_reflection_ = make_cleared_reflection(width, height);
  else
    ssr_.emplace(width, height, settings_.ssr);
}

void FramePipeline::render(const FrameState& frame, GpuTimer* timer) {
  raster_.render(frame, timer);
  GLuint reflection = no_reflection_.id();
  if (ssr_) {
    timed(timer, "ssr", [&] {
      ssr_->run({raster_.albedo_reflectivity(), raster_.world_position(), raster_.world_normal_roughness(),
                 raster_.lit(), raster_.frame_constants_buffer()});
    });
    reflection = ssr_->reflection();
  }
  timed(timer, "resolve", [&] { resolve_.run({raster_.lit(), raster_.albedo_reflectivity(), reflection}); });
}

ImageRgba8 FramePipeline::read_final() const {
  return quantize_to_rgba8(read_texture_rgbaf(resolve_.final_image(), kFinalFormat, width(), height()));
}

std::optional<SsrCounts> FramePipeline::read_counts() const {
  if (!ssr_) return std::nullopt;
  return ssr_->read_counts();
}

std::vector<DebugView> FramePipeline::read_debug_views() const {
  std::vector<DebugView> views;
  views.push_back({"albedo", albedo_view(raster_.read_rgbaf(RasterOutput::AlbedoReflectivity))});
  views.push_back({"normals", normal_view(raster_.read_rgbaf(RasterOutput::WorldNormalRoughness))});
  views.push_back({"positions", position_view(raster_.read_rgbaf(RasterOutput::WorldPosition), scene_->world_bounds())});
  views.push_back({"depth", depth_view(raster_.read_rgbaf(RasterOutput::WorldPosition), raster_.frame_constants())});
  views.push_back({"shadow_mask", grey_view(raster_.read_rgbaf(RasterOutput::ShadowMask))});
  if (ssr_) {
    views.push_back({"ssr_reflection",
                     reflection_view(read_texture_rgbaf(ssr_->reflection(), kReflectionFormat, width(), height()))});
    views.push_back({"failure_mask",
                     grey_view(read_texture_rgbaf(ssr_->failure_mask(), kFailureMaskFormat, width(), height()))});
  }
  return views;
}

}  // namespace glint::render
