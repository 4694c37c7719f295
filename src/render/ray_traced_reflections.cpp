#include "render/ray_traced_reflections.h"

#include "core/error.h"

#include <chrono>
#include <cmath>

namespace glint::render {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::unique_ptr<rt::RayTracer> built_tracer(const Scene& scene, const RayTracingSettings& settings) {
  settings.validate();
  std::unique_ptr<rt::RayTracer> tracer = rt::make_ray_tracer(settings.backend);
  tracer->build(scene, settings.accel);
  return tracer;
}

std::size_t pixel_count(int width, int height) {
  if (width <= 0 || height <= 0) fail("ray tracing: invalid frame size {}x{}", width, height);
  return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

void RayTracingSettings::validate() const {
  if (!(origin_offset_fraction >= 0.0f) || !(origin_offset_fraction < 0.1f))
    fail("ray tracing: origin offset fraction {} must be in [0, 0.1)", origin_offset_fraction);
  if (!(accel.auto_rebuild_sah_ratio >= 1.0f))
    fail("ray tracing: auto rebuild SAH ratio {} must be >= 1", accel.auto_rebuild_sah_ratio);
}

RayTracedReflections::RayTracedReflections(const Scene& scene, int width, int height,
                                           const RayTracingSettings& settings)
    : settings_(settings),
      tracer_(built_tracer(scene, settings)),
      buffers_(pixel_count(width, height)),
      ray_list_(width, height, buffers_),
      hit_shading_(width, height, buffers_) {
  const float diagonal = length(scene.world_bounds().extent());
  ray_list_.set_origin_offset(settings.origin_offset_fraction * (diagonal > 0.0f ? diagonal : 1.0f));
}

double RayTracedReflections::update_meshes(const Scene& scene, std::span<const std::uint32_t> dirty_meshes) {
  const auto start = Clock::now();
  tracer_->update(scene, dirty_meshes, settings_.update);
  return milliseconds_since(start);
}

RayTraceFrameStats RayTracedReflections::run(const RasterPipeline& raster, GLuint failure_mask, GLuint reflection,
                                             GpuTimer* timer) {
  run_timed_pass(timer, "ray_list", [&] {
    ray_list_.run({raster.albedo_reflectivity(), raster.world_position(), raster.world_normal_roughness(),
                   failure_mask, raster.frame_constants_buffer()});
  });
  const RayListCounts counts = buffers_.finish_ray_list();

  RayTraceFrameStats stats;
  stats.rays_traced = counts.rays;
  stats.reflective_pixels = counts.reflective;
  const auto trace_start = Clock::now();
  tracer_->trace_closest(buffers_.rays(counts.rays), buffers_.hits(counts.rays));
  stats.trace_ms = milliseconds_since(trace_start);

  run_timed_pass(timer, "hit_shade", [&] {
    hit_shading_.run({&raster.gpu_scene(), &raster.shadow_cube(), &raster.settings(), raster.frame_constants_buffer(),
                      reflection},
                     counts.rays);
  });
  return stats;
}

}  // namespace glint::render
