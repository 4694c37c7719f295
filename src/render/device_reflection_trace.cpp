#include "render/device_reflection_trace.h"

#include "core/error.h"
#include "gl/gl_pass_scope.h"
#include "render/hit_shadow_rays.h"

namespace glint::render {
namespace {

cuda::GlBufferInterop map_ray_buffers(const RayHitBuffers& buffers) {
  const cuda::InteropBuffer shared[] = {{buffers.ray_buffer(), cuda::InteropAccess::read_only},
                                        {buffers.hit_buffer(), cuda::InteropAccess::write_discard},
                                        {buffers.counter_buffer(), cuda::InteropAccess::read_only}};
  return cuda::GlBufferInterop(shared);
}

}  // namespace

DeviceReflectionTrace::DeviceReflectionTrace(rt::DeviceTracing& device, RayHitBuffers& buffers,
                                             HitShadowRays* hit_shadows)
    : device_(device), buffers_(buffers), hit_shadows_(hit_shadows), interop_(map_ray_buffers(buffers)) {}

std::uint32_t DeviceReflectionTrace::trace(std::size_t slot, vec3 light_position, GpuTimer* timer,
                                           const std::function<void()>& with_the_rays) {
  // A GPU pass from GL's side, so that the frame's GPU passes hold the CUDA segment too: GL's
  // commands after the unmap wait for the trace, so the pass spans the mapping, the traces and
  // the unmapping (docs/perf.md "Seventh round").
  std::optional<GpuTimer::PassScope> timed;
  if (timer != nullptr) timed.emplace(*timer, "device_trace");
  GlPassScope scope("trace");
  // Mapping orders the CUDA stream after the ray-list pass; unmapping orders hit shading after the
  // trace. An unmap followed by more CUDA work costs the frame about 0.3 ms on an H100 (docs/perf.md
  // "Seventh round"), so the frame's other traces (with_the_rays) go inside this mapping.
  cuda::ScopedInteropMap mapped(interop_, device_.stream());
  if (with_the_rays) with_the_rays();
  const auto* rays = mapped.pointer<const accel::Ray>(0);
  auto* hits = mapped.pointer<accel::Hit>(1);
  const auto* count = mapped.pointer<const std::uint32_t>(2);
  const auto capacity = static_cast<std::uint32_t>(buffers_.capacity());
  TraceTimes& times = times_[slot];
  times.closest.drop(device_);
  times.hit_shadows.drop(device_);
  if (hit_shadows_ && hit_shadows_->traced_with_hits()) {
    cuda::ScopedInteropMap shadow = hit_shadows_->answers().map_for_cuda();
    const rt::HitShadowRays request{light_position, hit_shadows_->origin_offset(), shadow.pointer<accel::Ray>(0),
                                    shadow.pointer<std::uint32_t>(1)};
    const rt::HitAndShadowTickets tickets =
        device_.trace_closest_and_hit_shadows_device(rays, hits, count, capacity, request);
    times.closest.unread = tickets.closest;
    times.hit_shadows.unread = tickets.shadows;
  } else {
    times.closest.unread = device_.trace_closest_device(rays, hits, count, capacity);
  }
  return capacity;
}

std::optional<RayTraceFrameStats> DeviceReflectionTrace::stats(std::size_t slot, bool wait) {
  const std::optional<RayListCounts> counts = buffers_.requested_counts(slot, wait);
  if (!counts) return std::nullopt;
  // The GPU passed the frame's hit shading, so its traces have ended: their times are there.
  TraceTimes& times = times_[slot];
  if (!times.closest.unread && !times.closest.ms)
    fail("device reflection trace: statistics of readback slot {} before its trace", slot);
  const std::optional<double> closest_ms = times.closest.read(device_, wait);
  if (!closest_ms) return std::nullopt;
  double hit_shadow_ms = 0.0;
  if (times.hit_shadows.unread || times.hit_shadows.ms) {
    const std::optional<double> ms = times.hit_shadows.read(device_, wait);
    if (!ms) return std::nullopt;
    hit_shadow_ms = *ms;
  }
  return RayTraceFrameStats{counts->rays, counts->reflective, *closest_ms + hit_shadow_ms, hit_shadow_ms};
}

std::optional<double> DeviceReflectionTrace::GpuTime::read(rt::DeviceTracing& device, bool wait) {
  if (!ms) {
    ms = device.gpu_ms(*unread, wait);
    if (!ms) return std::nullopt;
    unread.reset();
  }
  return ms;
}

void DeviceReflectionTrace::GpuTime::drop(rt::DeviceTracing& device) {
  if (unread) device.drop_ticket(*unread);
  *this = {};
}

}  // namespace glint::render
