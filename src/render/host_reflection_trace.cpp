#include "render/host_reflection_trace.h"

#include "core/stopwatch.h"
#include "gl/gl_pass_scope.h"

namespace glint::render {

std::uint32_t HostReflectionTrace::trace(std::size_t slot, vec3, GpuTimer*, const std::function<void()>& with_the_rays) {
  if (with_the_rays) with_the_rays();  // the CPU traces: no hand-over to share
  const RayListCounts counts = buffers_.finish_ray_list(slot);  // the mid-frame wait
  GlPassScope scope("trace");
  RayTraceFrameStats& stats = stats_[slot];
  stats = {counts.rays, counts.reflective, 0.0};
  const Stopwatch trace_watch;
  tracer_.trace_closest(buffers_.rays(counts.rays), buffers_.hits(counts.rays));
  stats.trace_ms = trace_watch.elapsed_ms();
  return counts.rays;
}

}  // namespace glint::render
