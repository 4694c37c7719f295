#pragma once
// RayTracedShadows: the shadow mask from shadow rays (ShadowMethod rt and hybrid, docs/render.md
// "Shadow methods"), between the G-buffer and lighting:
//   1. shadow_rays.comp.glsl: one ray per pixel, dense (in blocks of 8 x 4 pixels:
//      shadow_ray_index.h), from the G-buffer position (offset along the normal turned towards
//      the light) to the light; pixels
//      that need none (background, facing away from the light, hybrid: where the cube map's mask is
//      certain) get an empty ray (t_max < t_min) that tells step 3 their value;
//   2. the ray tracer's occlusion query over all width x height rays (OcclusionBuffers): a CPU
//      backend (cpu, embree) reads and writes persistently mapped host buffers after the CPU waited
//      for step 1 (a fence); a GPU backend (cuda, optix) gets the GL buffers mapped into CUDA
//      (trace_any_device, the ray count in a GL buffer too), so the host never waits;
//   3. shadow_ray_mask.comp.glsl: RasterTargets::shadow_mask from the answers (hybrid: the cube's
//      value where no ray was cast).
// The gl backend (rt::GlTracing) does all three in one dispatch instead (shadow_rays_inline.comp.glsl):
// each invocation makes its pixel's ray by the same rule, walks the tracer's structures itself
// (GlTracing::bind_inline_tracing) and writes the mask by the same rule, so the mask is the three
// steps' bit for bit without the ray list and answers between them (about 30 MB written and read
// back a frame at 1280x720, and two dispatches). RayTracingSettings::gl_inline_shadow_rays = false
// keeps the three steps (tests compare the two).
// The tracer is not owned: FramePipeline builds one for shadows and reflections alike.
//
//   RayTracedShadows shadows(scene, 1280, 720, ShadowMethod::rt, tracer, settings);
//   raster.render(frame, &timer, {.cube = false, .after_cube = [&] { shadows.run(raster); }});  // rt
#include "accel/ray.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/occlusion_buffers.h"
#include "render/shadow_method.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace glint::render {

class RasterPipeline;

class RayTracedShadows {
public:
  // `method` is rt or hybrid (glint::Error for cube); `tracer` must be built over `scene` and outlive
  // this. origin_offset_fraction: as RayTracingSettings', of the scene's bounding-box diagonal.
  // gl_inline: with the gl backend, trace inline (RayTracingSettings::gl_inline_shadow_rays).
  // Needs a current GL context.
  RayTracedShadows(const Scene& scene, int width, int height, ShadowMethod method, rt::RayTracer& tracer,
                   float origin_offset_fraction, float depth_edge_fraction, bool gl_inline = true);
  // Writes raster.shadow_mask() from this frame's G-buffer (and, hybrid, the cube map's mask, which
  // must be in shadow_mask() already): inline, one dispatch; otherwise write_rays(), trace(),
  // write_mask(), and with a CPU backend the CPU waits for step 1 in between. Ends with a barrier that
  // makes the mask visible to texture fetches, image loads and readbacks.
  void run(const RasterPipeline& raster);
  // Whether run() traces inline (the gl backend): then the three steps below are not to be called.
  bool traces_inline() const { return inline_gl_ != nullptr; }
  // The three steps apart, for FramePipeline, which traces the shadow rays in the same GL-CUDA
  // hand-over as the reflection rays (docs/render.md "One hand-over a frame"). write_mask() ends
  // with a barrier that makes the mask visible to texture fetches, image loads and readbacks.
  // glint::Error when tracing inline.
  void write_rays(const RasterPipeline& raster);
  void trace();
  // trace() in two halves (OcclusionBuffers::start_trace): FramePipeline starts the shadow rays'
  // trace inside the reflection trace's mapping and finishes it after the reflection rays.
  void start_trace();
  void finish_trace() { steps().finish_trace(); }
  void write_mask(const RasterPipeline& raster);

  // CPU backends: the last run's rays and answers (one byte per ray), for tests; glint::Error for
  // a GPU backend, whose rays stay in GPU memory, and when tracing inline (no rays are kept).
  std::span<const accel::Ray> rays() const { return steps().rays(); }
  std::span<const std::uint8_t> occluded() const { return steps().occluded(); }

  ShadowMethod method() const { return method_; }

private:
  OcclusionBuffers& steps();  // the three steps' buffers; glint::Error when tracing inline
  const OcclusionBuffers& steps() const;
  void trace_inline(const RasterPipeline& raster);

  ShadowMethod method_;
  int width_, height_;
  rt::GlTracing* inline_gl_;  // the gl backend's, when tracing inline; else null
  // The three steps: the rays and answers, the ray and mask programs.
  std::optional<OcclusionBuffers> buffers_;
  std::optional<ShaderProgram> ray_program_, mask_program_;
  // Inline: the one program, and (hybrid) a copy of the cube's mask that the rule reads while the
  // pass writes the mask itself.
  std::optional<ShaderProgram> inline_program_;
  GlTexture cube_mask_copy_;
};

}  // namespace glint::render
