#include "render/gl_reflection_trace.h"

namespace glint::render {

std::uint32_t GlReflectionTrace::trace(std::size_t, vec3, GpuTimer* timer, const std::function<void()>& with_the_rays) {
  if (with_the_rays) with_the_rays();  // GL passes all: no hand-over to share
  const auto capacity = static_cast<std::uint32_t>(buffers_.capacity());
  run_timed_pass(timer, "trace", [&] {
    gl_.trace_closest_gl(buffers_.ray_buffer(), buffers_.hit_buffer(), buffers_.counter_buffer(), capacity);
  });
  return capacity;
}

std::optional<RayTraceFrameStats> GlReflectionTrace::stats(std::size_t slot, bool wait) {
  const std::optional<RayListCounts> counts = buffers_.requested_counts(slot, wait);
  if (!counts) return std::nullopt;
  return RayTraceFrameStats{counts->rays, counts->reflective, 0.0};  // trace_ms: FrameLoop's "trace" pass
}

}  // namespace glint::render
