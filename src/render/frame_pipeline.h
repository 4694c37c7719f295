#pragma once
// One frame of glint's renderer, in order: the raster passes (G-buffer, shadow, light), SSR when
// reflections are on, then resolve (fade, blur, composite, tone map). Every pass is timed under
// its name in kFramePassNames when a GpuTimer is given; the frame's final image stays on the GPU
// until read_final() copies it out.
//
//   FramePipeline pipeline(scene, 1280, 720, settings);
//   timer.begin_frame();
//   pipeline.render(animation.at(frame), &timer);
//   timer.end_frame();
//   write_png(path, pipeline.read_final());
#include "core/image.h"
#include "gl/gl_objects.h"
#include "gl/gpu_timer.h"
#include "render/raster_pipeline.h"
#include "render/raster_settings.h"
#include "render/reflection_mode.h"
#include "render/resolve_pass.h"
#include "render/resolve_settings.h"
#include "render/ssr_pass.h"
#include "render/ssr_settings.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint::render {

// Timer names of the passes, in the order timings.csv lists them (not the order they run:
// the shadow mask needs the G-buffer, so "gbuffer" runs first).
inline constexpr std::string_view kFramePassNames[] = {"shadow", "gbuffer", "light", "ssr", "resolve"};

struct FramePipelineSettings {
  ReflectionMode reflections = ReflectionMode::ssr;
  RasterSettings raster;
  SsrSettings ssr;
  ResolveSettings resolve;

  void validate() const;  // throws glint::Error naming the first bad setting
};

// An image a frame produced besides the final one, made viewable as 8-bit RGBA.
struct DebugView {
  std::string name;  // file-name friendly: "albedo", "normals", ...
  ImageRgba8 image;
};

class FramePipeline {
public:
  // Uploads `scene` (which must outlive the pipeline, see RasterPipeline) and compiles every pass.
  // Needs a current GL context.
  FramePipeline(const Scene& scene, int width, int height, const FramePipelineSettings& settings = {});

  void render(const FrameState& frame, GpuTimer* timer = nullptr);

  // The last frame's output, sRGB-encoded, top row first. Waits for the GPU.
  ImageRgba8 read_final() const;
  // Reflective and SSR-failed pixels of the last frame; nullopt when reflections are off (SSR did not
  // run, so nothing was counted). Waits for the GPU.
  std::optional<SsrCounts> read_counts() const;
  // albedo, normals, positions, depth, shadow mask, and with SSR the reflection and failure mask.
  // Waits for the GPU; see debug_views.h for how each is made viewable.
  std::vector<DebugView> read_debug_views() const;

  RasterPipeline& raster() { return raster_; }
  const RasterPipeline& raster() const { return raster_; }
  const FramePipelineSettings& settings() const { return settings_; }
  int width() const { return raster_.width(); }
  int height() const { return raster_.height(); }

private:
  const Scene* scene_;
  FramePipelineSettings settings_;
  RasterPipeline raster_;
  std::optional<SsrPass> ssr_;
  ResolvePass resolve_;
  GlTexture no_reflection_;  // all zero: what resolve reads when reflections are off
};

}  // namespace glint::render
