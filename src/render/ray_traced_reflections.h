#pragma once
// The ray-traced complement of the hybrid renderer (the paper's Sec. III-C), as three steps around a
// RayTracer backend:
//   1. RayListPass (GPU): the pixels that need a ray (SSR-failed, or every reflective one in rt mode)
//      become a list of mirror rays;
//   2. the backend traces the list into hit records: a CPU backend (cpu, embree) in persistently
//      mapped host memory, after the CPU waited for the list; a GPU backend (cuda, optix) in GPU
//      memory shared with CUDA, with no host wait and no copy (rt::DeviceTracing,
//      cuda::GlBufferInterop); the gl backend in GPU memory with its compute shaders, a GL pass
//      timed as "trace" (rt::GlTracing). Which of the three is chosen once, at construction
//      (render/reflection_trace_step.h);
//   3. HitShadingPass (GPU): the hits are shaded like the raster path into the reflection image.
// The tracer is not owned: FramePipeline builds one (build_ray_tracer) for reflections and shadow
// rays alike and updates it once per frame for deforming meshes.
//
//   auto tracer = build_ray_tracer(scene, settings);               // shared with shadow rays
//   RayTracedReflections traced(scene, 1280, 720, settings, *tracer);
//   traced.run(raster, ssr.failure_mask(), ssr.reflection(), &timer);
#include "gl/gpu_timer.h"
#include "render/hit_shading_pass.h"
#include "render/hit_shadow_rays.h"
#include "render/raster_pipeline.h"
#include "render/ray_hit_buffers.h"
#include "render/ray_list_pass.h"
#include "render/reflection_trace_step.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glint::render {

struct RayTracingSettings {
  std::string backend = "cpu";  // rt::make_ray_tracer name: cpu or embree
  rt::AccelOptions accel;       // structure of the cpu backend's BLASes, SAH costs, auto threshold
  rt::UpdatePolicy update = rt::UpdatePolicy::rebuild;
  // Empty: rays see every instance. Otherwise only these (indices into Scene::instances) are traced
  // and the rest of the scene is invisible to the rays (rt::InstanceSubsetTracer; glint bench Fig. 10).
  std::vector<std::uint32_t> traced_instances;
  // Ray origins move this fraction of the scene's bounding-box diagonal along the surface normal
  // (enough to leave a flat surface at float precision, far below a visible gap).
  float origin_offset_fraction = 1e-4f;
  // The gl backend traces the dense shadow rays inline, in the pass that makes them (rt::GlTracing::
  // bind_inline_tracing): made, traced and turned into the mask in one dispatch (RayTracedShadows).
  // false: the three steps the other backends take (ray list, trace_any_gl, mask), kept so that
  // tests can compare the two; other backends ignore it. The reflection hits' shadow rays take the
  // three steps: made and traced in one pass they took twice as long on an H100 (docs/perf.md
  // "Eleventh round").
  bool gl_inline_shadow_rays = true;

  void validate() const;  // glint::Error naming the first bad field (an unknown backend: at construction)
};

// The settings' backend (with traced_instances: only those), its structures built over `scene`
// (timed: stats().build_ms). glint::Error for bad settings or an unknown backend.
std::unique_ptr<rt::RayTracer> build_ray_tracer(const Scene& scene, const RayTracingSettings& settings);

class RayTracedReflections {
public:
  // Creates the buffers and passes for width x height around `tracer` (built over `scene`, e.g. by
  // build_ray_tracer; it must outlive this). Needs a current GL context.
  // With `shadow_rays` (rt and hybrid shadows) each hit's shadow is a shadow ray through the same
  // tracer (HitShadowRays), else the cube map's.
  RayTracedReflections(const Scene& scene, int width, int height, const RayTracingSettings& settings,
                       rt::RayTracer& tracer, bool shadow_rays = false);
  // The passes and the trace step hold references to the buffers: not copyable or movable.
  RayTracedReflections(const RayTracedReflections&) = delete;
  RayTracedReflections& operator=(const RayTracedReflections&) = delete;

  // Lists, traces and shades the reflections of this frame into `reflection` (kReflectionFormat),
  // written only at listed pixels. `failure_mask` 0 = trace every reflective pixel. The GL steps
  // are timed as "ray_list" and "hit_shade"; with a CPU backend the CPU waits for the ray list in
  // between, with a GPU backend nothing waits. The frame's statistics come from take_stats() (runs
  // are numbered 0, 1, ...; the last kFramesInFlight are kept) or frame_stats().
  void run(const RasterPipeline& raster, GLuint failure_mask, GLuint reflection, GpuTimer* timer);
  std::uint64_t runs() const { return runs_; }

  // run()'s three steps apart, in this order, for FramePipeline: the ray list needs only the
  // G-buffer (and the failure mask), hit shading neither the lit image nor the shadow mask, so the
  // frame's other traces can go between them in the same GL-CUDA hand-over (docs/render.md "One
  // hand-over a frame"). trace(): `with_the_rays` is work to issue in the same hand-over, before
  // the reflection rays (FramePipeline: the shadow rays' trace); a device backend issues it inside
  // its mapping, a host or gl backend just before its own trace. Returns what shade() needs.
  void list(const RasterPipeline& raster, GLuint failure_mask, GpuTimer* timer);
  std::uint32_t trace(const RasterPipeline& raster, GpuTimer* timer,
                      const std::function<void()>& with_the_rays = {});
  void shade(const RasterPipeline& raster, GLuint reflection, std::uint32_t listed, GpuTimer* timer);

  // The statistics of run `run`, one of the last kFramesInFlight. CPU backends know them at once;
  // with a GPU backend they come from a readback slot and CUDA events: nullopt while the GPU has
  // not finished that frame and `wait` is false. glint::Error for an older or a future run.
  std::optional<RayTraceFrameStats> take_stats(std::uint64_t run, bool wait);
  // The statistics of the last run(); with a GPU backend, waits for that frame's GPU work first.
  RayTraceFrameStats frame_stats();

  const rt::RayTracer& tracer() const { return *tracer_; }
  rt::RayTracer& tracer() { return *tracer_; }
  const RayTracingSettings& settings() const { return settings_; }
  RayListPass& ray_list() { return ray_list_; }  // --reflections auto sets its tiles and budget
  // The rays and hits of the last run (tests), and the hits' shadow rays (null without shadow rays).
  const RayHitBuffers& ray_buffers() const { return buffers_; }
  const HitShadowRays* hit_shadow_rays() const { return hit_shadows_ ? &*hit_shadows_ : nullptr; }

private:
  std::size_t slot_of(std::uint64_t run) const;

  RayTracingSettings settings_;
  rt::RayTracer* tracer_;
  RayHitBuffers buffers_;
  std::uint64_t runs_ = 0;
  RayListPass ray_list_;
  std::optional<HitShadowRays> hit_shadows_;  // with shadow rays
  HitShadingPass hit_shading_;
  // The backend's trace between the ray list and hit shading, per readback slot (run %
  // kFramesInFlight); made last, over buffers_ and hit_shadows_.
  std::unique_ptr<ReflectionTraceStep> trace_step_;
};

}  // namespace glint::render
