#pragma once
// Shadow rays and the occlusion query's answers between GL and a ray tracer (RayTracedShadows: one
// ray per pixel; RayTracedReflections: one per reflection hit), created once for `capacity` rays:
//  - CPU backends (cpu, embree): both in host memory, mapped persistently (persistent_buffer.h), so
//    trace_any reads the rays and writes one byte per ray in place, after the CPU waited for the
//    pass that wrote the rays (a fence);
//  - GPU backends (cuda, optix): both in GPU memory, shared with CUDA once (GlBufferInterop) and
//    mapped around each trace_any_device (one uint per ray; the count, `capacity`, sits in a GL
//    buffer too), so the host never waits;
//  - the gl backend: both in GPU memory, traced by its compute shaders (rt::GlTracing) like any
//    other GL pass: no mapping, no hand-over.
//   rays     (kShadowRayBinding):       accel::Ray[capacity]; an empty ray (t_min > t_max) is never occluded
//   answers  (kShadowOcclusionBinding): uint[], read in GLSL by occlusion_flag.glsl's
//            `occluded(i)` with the flag_bytes() uniform (4: a uint per ray, 1: four bytes to a uint)
// With RayQuery::closest (PrimaryRayPass: camera rays) the same buffers answer the closest-hit
// query instead: the answers are accel::Hit[capacity] on every backend (trace_closest,
// trace_closest_device; std430 `struct { float t; uint instance, prim; float u, v; }`).
#include "accel/ray.h"
#include "cuda/gl_buffer_interop.h"
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"
#include "rt/ray_tracer.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace glint::render {

// Storage bindings of the shadow rays and their answers (1..5 are the scene's, 6..9 the reflection
// rays': render_targets.h).
inline constexpr GLuint kShadowRayBinding = 10;
inline constexpr GLuint kShadowOcclusionBinding = 11;

// Which query trace() asks: any hit (occlusion flags) or the closest hit (accel::Hit per ray).
enum class RayQuery { any, closest };

class OcclusionBuffers {
public:
  // `tracer` must outlive this. glint::Error for capacity 0. Needs a current GL context.
  OcclusionBuffers(std::size_t capacity, rt::RayTracer& tracer, const char* what, RayQuery query = RayQuery::any);
  OcclusionBuffers(const OcclusionBuffers&) = delete;  // owns mapped pointers
  OcclusionBuffers& operator=(const OcclusionBuffers&) = delete;

  void bind() const;  // rays and answers to their storage bindings
  int flag_bytes() const { return device_ || gl_ ? 4 : 1; }
  // Whether the gl backend traces them (GL dispatches; trace() may take a GL count buffer).
  bool traces_on_gl() const { return gl_ != nullptr; }

  // After the pass that wrote the rays was issued (and a shader-storage barrier): answers them.
  // CPU backends trace the first `host_count` rays after waiting for the GPU; GPU backends trace
  // all `capacity` on the tracer's stream (rays past the frame's count must be empty). The gl
  // backend reads how many from the first uint of `gl_count` where given (a GL buffer the pass that
  // wrote the rays also counted in, so that it need not trace, nor write, the empty rays past it),
  // else traces `capacity` as well.
  void trace(std::size_t host_count, GLuint gl_count = 0);
  // trace() in two halves: a GPU backend keeps the buffers mapped into CUDA from start_trace() to
  // finish_trace(), so that a caller enqueuing more CUDA work in between (FramePipeline: the
  // reflection rays) unmaps only after all of it: an unmap followed by more CUDA work costs the
  // frame a GL-CUDA round trip (docs/perf.md "Seventh round"). Other backends trace in start_trace().
  void start_trace(std::size_t host_count, GLuint gl_count = 0);
  void finish_trace();

  // GPU backends: rays (pointer 0), answers (1) and count (2) mapped into CUDA on the tracer's
  // stream until the returned map goes, for CUDA work the caller enqueues itself (RayTracedReflections
  // traces the hits' shadow rays with the hits); glint::Error for a CPU backend.
  cuda::ScopedInteropMap map_for_cuda();

  // CPU backends: the rays and answers of the last trace, for tests; glint::Error for a GPU backend.
  std::span<const accel::Ray> rays() const;
  std::span<const std::uint8_t> occluded() const;
  std::span<const accel::Hit> hits() const;  // RayQuery::closest
  std::size_t capacity() const { return capacity_; }

private:
  std::size_t capacity_;
  const char* what_;
  RayQuery query_;
  rt::RayTracer* tracer_;
  rt::DeviceTracing* device_;  // tracer_'s device side, or null
  rt::GlTracing* gl_;          // tracer_'s GL side (the gl backend), or null
  GlBuffer rays_, occluded_;
  GlBuffer ray_count_;  // one uint, `capacity`: what the GPU backends read on the GPU
  accel::Ray* mapped_rays_ = nullptr;        // CPU backends
  std::uint8_t* mapped_occluded_ = nullptr;  // CPU backends (closest: the accel::Hit array's bytes)
  std::optional<ReadbackRing> ray_fence_;    // CPU backends: the wait for the rays
  std::optional<cuda::GlBufferInterop> interop_;  // GPU backends: rays, answers, count
  std::optional<cuda::ScopedInteropMap> held_map_;  // GPU backends, from start_trace() to finish_trace()
};

}  // namespace glint::render
