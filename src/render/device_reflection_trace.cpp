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

std::uint32_t DeviceReflectionTrace::trace(std::size_t slot, vec3 light_position, GpuTimer*) {
  GlPassScope scope("trace");
  // Mapping orders the CUDA stream after the ray-list pass; unmapping orders hit shading after the
  // trace. Both happen on the GPU: the host only enqueues.
  cuda::ScopedInteropMap mapped(interop_, device_.stream());
  const auto* rays = mapped.pointer<const accel::Ray>(0);
  auto* hits = mapped.pointer<accel::Hit>(1);
  const auto* count = mapped.pointer<const std::uint32_t>(2);
  const auto capacity = static_cast<std::uint32_t>(buffers_.capacity());
  TraceTime& time = times_[slot];
  if (time.unread) device_.drop_ticket(*time.unread);
  time = {};
  if (hit_shadows_ && hit_shadows_->traced_with_hits()) {
    cuda::ScopedInteropMap shadow = hit_shadows_->answers().map_for_cuda();
    const rt::HitShadowRays request{light_position, hit_shadows_->origin_offset(), shadow.pointer<accel::Ray>(0),
                                    shadow.pointer<std::uint32_t>(1)};
    const rt::HitAndShadowTickets tickets =
        device_.trace_closest_and_hit_shadows_device(rays, hits, count, capacity, request);
    time.unread = tickets.closest;
    device_.drop_ticket(tickets.shadows);  // the frame's trace time is the closest-hit trace's
  } else {
    time.unread = device_.trace_closest_device(rays, hits, count, capacity);
  }
  return capacity;
}

std::optional<RayTraceFrameStats> DeviceReflectionTrace::stats(std::size_t slot, bool wait) {
  const std::optional<RayListCounts> counts = buffers_.requested_counts(slot, wait);
  if (!counts) return std::nullopt;
  // The GPU passed the frame's hit shading, so its trace has ended: the time is there.
  TraceTime& time = times_[slot];
  if (!time.ms) {
    if (!time.unread) fail("device reflection trace: statistics of readback slot {} before its trace", slot);
    time.ms = device_.gpu_ms(*time.unread, wait);
    if (!time.ms) return std::nullopt;
    time.unread.reset();
  }
  return RayTraceFrameStats{counts->rays, counts->reflective, *time.ms};
}

}  // namespace glint::render
