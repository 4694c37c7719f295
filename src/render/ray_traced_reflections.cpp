#include "render/ray_traced_reflections.h"

#include "backends/registry.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "gl/gl_pass_scope.h"
#include "rt/instance_subset_tracer.h"

#include <cmath>
#include <utility>

namespace glint::render {
namespace {

RayHitMemory buffer_memory(rt::RayTracer& tracer) {
  return tracer.device_tracing() || tracer.gl_tracing() ? RayHitMemory::device : RayHitMemory::host_mapped;
}

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
      device_(tracer_->device_tracing()),
      gl_(tracer_->gl_tracing()),
      buffers_(pixel_count(width, height), buffer_memory(*tracer_)),
      ray_list_(width, height, buffers_),
      hit_shading_(width, height, buffers_) {
  if (device_) {
    const cuda::InteropBuffer shared[] = {{buffers_.ray_buffer(), cuda::InteropAccess::read_only},
                                          {buffers_.hit_buffer(), cuda::InteropAccess::write_discard},
                                          {buffers_.counter_buffer(), cuda::InteropAccess::read_only}};
    interop_.emplace(shared);
  }
  const float diagonal = length(scene.world_bounds().extent());
  const float origin_offset = settings.origin_offset_fraction * (diagonal > 0.0f ? diagonal : 1.0f);
  ray_list_.set_origin_offset(origin_offset);
  if (shadow_rays) hit_shadows_.emplace(buffers_.capacity(), tracer, origin_offset);
}

std::size_t RayTracedReflections::slot_of(std::uint64_t run) const {
  if (run >= runs_ || runs_ - run > kFramesInFlight)
    fail("ray tracing: statistics of run {} asked after {} runs (the last {} are kept)", run, runs_, kFramesInFlight);
  return static_cast<std::size_t>(run % kFramesInFlight);
}

void RayTracedReflections::run(const RasterPipeline& raster, GLuint failure_mask, GLuint reflection, GpuTimer* timer) {
  const auto slot = static_cast<std::size_t>(runs_ % kFramesInFlight);
  run_timed_pass(timer, "ray_list", [&] {
    ray_list_.run({raster.albedo_reflectivity(), raster.world_position(), raster.world_normal_roughness(),
                   failure_mask, raster.frame_constants_buffer()});
  });
  // A CPU backend needs the list in host memory now; a GPU backend reads the count on the GPU.
  const bool on_host = device_ == nullptr && gl_ == nullptr;
  const RayListCounts host_counts = on_host ? buffers_.finish_ray_list(slot) : RayListCounts{};
  if (gl_) {
    run_timed_pass(timer, "trace", [&] {
      gl_->trace_closest_gl(buffers_.ray_buffer(), buffers_.hit_buffer(), buffers_.counter_buffer(),
                            static_cast<std::uint32_t>(buffers_.capacity()));
    });
  } else {
    { GlPassScope scope("trace"); trace(host_counts, slot, raster.frame_constants().light_position_range); }
  }
  const auto max_rays = static_cast<std::uint32_t>(on_host ? host_counts.rays : buffers_.capacity());
  run_timed_pass(timer, "hit_shade", [&] {
    // The hits' shadow rays are part of shading them (a CPU backend waits for their list here).
    if (hit_shadows_) hit_shadows_->run(buffers_, raster.gpu_scene(), raster.frame_constants_buffer(), max_rays);
    hit_shading_.run({&raster.gpu_scene(), &raster.shadow_cube(), &raster.settings(), raster.frame_constants_buffer(),
                      reflection, hit_shadows_ ? &hit_shadows_->answers() : nullptr},
                     max_rays);
  });
  if (!on_host) buffers_.request_counts(slot);  // read frames later, when the GPU is past them
  ++runs_;
}

void RayTracedReflections::trace(RayListCounts host_counts, std::size_t slot, vec3 light_position) {
  if (!device_) {
    RayTraceFrameStats& stats = slot_stats_[slot];
    stats = {host_counts.rays, host_counts.reflective, 0.0};
    const Stopwatch trace_watch;
    tracer_->trace_closest(buffers_.rays(host_counts.rays), buffers_.hits(host_counts.rays));
    stats.trace_ms = trace_watch.elapsed_ms();
    return;
  }
  // Mapping orders the CUDA stream after the ray-list pass; unmapping orders hit shading after the
  // trace. Both happen on the GPU: the host only enqueues.
  cuda::ScopedInteropMap mapped(*interop_, device_->stream());
  const auto* rays = mapped.pointer<const accel::Ray>(0);
  auto* hits = mapped.pointer<accel::Hit>(1);
  const auto* count = mapped.pointer<const std::uint32_t>(2);
  const auto capacity = static_cast<std::uint32_t>(buffers_.capacity());
  if (hit_shadows_ && hit_shadows_->traced_with_hits()) {
    cuda::ScopedInteropMap shadow = hit_shadows_->answers().map_for_cuda();
    const rt::HitShadowRays request{light_position, hit_shadows_->origin_offset(), shadow.pointer<accel::Ray>(0),
                                    shadow.pointer<std::uint32_t>(1)};
    trace_tickets_[slot] = device_->trace_closest_and_hit_shadows_device(rays, hits, count, capacity, request).closest;
  } else {
    trace_tickets_[slot] = device_->trace_closest_device(rays, hits, count, capacity);
  }
}

std::optional<RayTraceFrameStats> RayTracedReflections::take_stats(std::uint64_t run, bool wait) {
  const std::size_t slot = slot_of(run);
  if (device_ == nullptr && gl_ == nullptr) return slot_stats_[slot];
  const std::optional<RayListCounts> counts = buffers_.requested_counts(slot, wait);
  if (!counts) return std::nullopt;
  // The gl backend's trace is a GL pass, timed by the frame's timer as "trace" (FrameLoop puts it here).
  if (gl_) return RayTraceFrameStats{counts->rays, counts->reflective, 0.0};
  // The GPU passed the frame's hit shading, so its trace has ended: the time is there.
  const std::optional<double> trace_ms = device_->gpu_ms(trace_tickets_[slot], wait);
  if (!trace_ms) return std::nullopt;
  return RayTraceFrameStats{counts->rays, counts->reflective, *trace_ms};
}

RayTraceFrameStats RayTracedReflections::frame_stats() {
  if (runs_ == 0) fail("ray tracing: statistics asked before the first frame");
  return *take_stats(runs_ - 1, /*wait=*/true);
}

}  // namespace glint::render
