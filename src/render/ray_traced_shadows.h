#pragma once
// RayTracedShadows: the shadow mask from shadow rays (ShadowMethod rt and hybrid, docs/render.md
// "Shadow methods"), between the G-buffer and lighting:
//   1. shadow_rays.comp.glsl: one ray per pixel, dense (ray i is pixel y * width + x), from the
//      G-buffer position (offset along the normal turned towards the light) to the light; pixels
//      that need none (background, facing away from the light, hybrid: where the cube map's mask is
//      certain) get an empty ray (t_max < t_min) that tells step 3 their value;
//   2. the ray tracer's occlusion query over all width x height rays: a CPU backend (cpu, embree)
//      reads and writes persistently mapped host buffers after the CPU waited for step 1 (a fence);
//      a GPU backend (cuda, optix) gets the GL buffers mapped into CUDA (trace_any_device, the ray
//      count in a GL buffer too), so the host never waits;
//   3. shadow_ray_mask.comp.glsl: RasterTargets::shadow_mask from the answers (hybrid: the cube's
//      value where no ray was cast).
// The tracer is not owned: FramePipeline builds one for shadows and reflections alike.
//
//   RayTracedShadows shadows(scene, 1280, 720, ShadowMethod::rt, tracer, settings);
//   raster.render(frame, &timer, {.cube = false, .after_cube = [&] { shadows.run(raster); }});  // rt
#include "accel/ray.h"
#include "cuda/gl_buffer_interop.h"
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"
#include "gl/shader_program.h"
#include "render/shadow_method.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace glint::render {

class RasterPipeline;

// Storage bindings of the shadow rays and their answers (1..5 are the scene's, 6..9 the reflection
// rays': render_targets.h).
inline constexpr GLuint kShadowRayBinding = 10;        // accel::Ray[width * height]
inline constexpr GLuint kShadowOcclusionBinding = 11;  // the occlusion query's answers, see the shader

class RayTracedShadows {
public:
  // `method` is rt or hybrid (glint::Error for cube); `tracer` must be built over `scene` and outlive
  // this. origin_offset_fraction: as RayTracingSettings', of the scene's bounding-box diagonal.
  // Needs a current GL context.
  RayTracedShadows(const Scene& scene, int width, int height, ShadowMethod method, rt::RayTracer& tracer,
                   float origin_offset_fraction, float depth_edge_fraction);
  RayTracedShadows(const RayTracedShadows&) = delete;  // owns mapped pointers
  RayTracedShadows& operator=(const RayTracedShadows&) = delete;

  // Writes raster.shadow_mask() from this frame's G-buffer (and, hybrid, the cube map's mask, which
  // must be in shadow_mask() already). Ends with a barrier that makes the mask visible to texture
  // fetches, image loads and readbacks. With a CPU backend the CPU waits for step 1 in between.
  void run(const RasterPipeline& raster);

  // CPU backends: the last run's rays and answers (one byte per ray), for tests; glint::Error for
  // a GPU backend, whose rays stay in GPU memory.
  std::span<const accel::Ray> rays() const;
  std::span<const std::uint8_t> occluded() const;

  ShadowMethod method() const { return method_; }
  std::size_t ray_capacity() const { return pixels_; }

private:
  ShadowMethod method_;
  rt::RayTracer* tracer_;
  rt::DeviceTracing* device_;  // tracer_'s device side, or null
  int width_, height_;
  std::size_t pixels_;
  GlBuffer rays_, occluded_;
  GlBuffer ray_count_;  // one uint: width * height, read by the GPU backends on the GPU
  accel::Ray* mapped_rays_ = nullptr;         // CPU backends
  std::uint8_t* mapped_occluded_ = nullptr;   // CPU backends
  std::optional<ReadbackRing> ray_fence_;     // CPU backends: the wait for step 1
  std::optional<cuda::GlBufferInterop> interop_;  // GPU backends: rays, answers, count
  ShaderProgram ray_program_, mask_program_;
};

}  // namespace glint::render
