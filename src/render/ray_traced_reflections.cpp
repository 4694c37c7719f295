#include "render/ray_traced_reflections.h"

#include "backends/registry.h"
#include "core/error.h"
#include "render/ray_origin_offset.h"
#include "rt/instance_subset_tracer.h"

#include <cmath>
#include <utility>

namespace glint::render {
namespace {

std::size_t pixel_count(int width, int height) {
  if (width <= 0 || height <= 0) fail("ray tracing: invalid frame size {}x{}", width, height);
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

std::unique_ptr<rt::RayTracer> build_ray_tracer(const Scene& scene, const RayTracingSettings& settings) {
  settings.validate();
  std::unique_ptr<rt::RayTracer> tracer = backends::make_ray_tracer(settings.backend);
  if (!settings.traced_instances.empty())
    tracer = std::make_unique<rt::InstanceSubsetTracer>(std::move(tracer), settings.traced_instances);
  tracer->build(scene, settings.accel);
  return tracer;
}

void RayTracingSettings::validate() const {
  if (!(origin_offset_fraction >= 0.0f) || !(origin_offset_fraction < 0.1f))
    fail("ray tracing: origin offset fraction {} must be in [0, 0.1)", origin_offset_fraction);
  if (!(accel.auto_rebuild_sah_ratio >= 1.0f))
    fail("ray tracing: auto rebuild SAH ratio {} must be >= 1", accel.auto_rebuild_sah_ratio);
}

RayTracedReflections::RayTracedReflections(const Scene& scene, int width, int height,
                                           const RayTracingSettings& settings, rt::RayTracer& tracer,
                                           bool shadow_rays)
    : settings_(settings),
      tracer_(&tracer),
      buffers_(pixel_count(width, height), reflection_ray_memory(tracer)),
      ray_list_(width, height, buffers_),
      hit_shading_(width, height, buffers_) {
  const float origin_offset = ray_origin_offset(settings.origin_offset_fraction, scene.world_bounds());
  ray_list_.set_origin_offset(origin_offset);
  if (shadow_rays) hit_shadows_.emplace(buffers_.capacity(), tracer, origin_offset);
  trace_step_ = make_reflection_trace_step(tracer, buffers_, hit_shadows_ ? &*hit_shadows_ : nullptr);
}

std::size_t RayTracedReflections::slot_of(std::uint64_t run) const {
  if (run >= runs_ || runs_ - run > kFramesInFlight)
    fail("ray tracing: statistics of run {} asked after {} runs (the last {} are kept)", run, runs_, kFramesInFlight);
  return static_cast<std::size_t>(run % kFramesInFlight);
}

void RayTracedReflections::run(const RasterPipeline& raster, GLuint failure_mask, GLuint reflection, GpuTimer* timer) {
  list(raster, failure_mask, timer);
  const std::uint32_t listed = trace(raster, timer);
  shade(raster, reflection, listed, timer);
}

void RayTracedReflections::list(const RasterPipeline& raster, GLuint failure_mask, GpuTimer* timer) {
  run_timed_pass(timer, "ray_list", [&] {
    ray_list_.run({raster.albedo_reflectivity(), raster.world_position(), raster.world_normal_roughness(),
                   failure_mask, raster.frame_constants_buffer()});
  });
}

std::uint32_t RayTracedReflections::trace(const RasterPipeline& raster, GpuTimer* timer,
                                          const std::function<void()>& with_the_rays) {
  const auto slot = static_cast<std::size_t>(runs_ % kFramesInFlight);
  return trace_step_->trace(slot, raster.frame_constants().light_position_range, timer, with_the_rays);
}

void RayTracedReflections::shade(const RasterPipeline& raster, GLuint reflection, std::uint32_t listed,
                                 GpuTimer* timer) {
  run_timed_pass(timer, "hit_shade", [&] {
    // The hits' shadow rays are part of shading them (a CPU backend waits for their list here).
    if (hit_shadows_) hit_shadows_->run(buffers_, raster.gpu_scene(), raster.frame_constants_buffer(), listed);
    hit_shading_.run({&raster.gpu_scene(), &raster.shadow_cube(), &raster.settings(), raster.frame_constants_buffer(),
                      reflection, hit_shadows_ ? &hit_shadows_->answers() : nullptr, raster.world_normal_roughness()},
                     listed);
  });
  trace_step_->finish(static_cast<std::size_t>(runs_ % kFramesInFlight));
  ++runs_;
}

std::optional<RayTraceFrameStats> RayTracedReflections::take_stats(std::uint64_t run, bool wait) {
  return trace_step_->stats(slot_of(run), wait);
}

RayTraceFrameStats RayTracedReflections::frame_stats() {
  if (runs_ == 0) fail("ray tracing: statistics asked before the first frame");
  return *take_stats(runs_ - 1, /*wait=*/true);
}

}  // namespace glint::render
