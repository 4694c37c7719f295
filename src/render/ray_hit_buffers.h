#pragma once
// The buffers through which rays and hit records move between GL and a ray tracer, created once at
// a capacity of one ray per pixel, so a frame allocates nothing. Two kinds of memory:
//  - host_mapped (CPU backends): rays and hits live in host memory, mapped persistently
//    (GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT), so the tracer reads and writes them in place and
//    a frame copies nothing but the two counters;
//  - device (GPU backends): rays and hits stay in GPU memory, shared with CUDA (GlBufferInterop),
//    and the counters are read back only after the frame, for statistics.
//   rays     (kRayBinding):        accel::Ray[capacity]  the ray-list pass writes, the CPU reads
//   pixels   (kRayPixelBinding):   uint[capacity]        y * width + x of ray i; GPU only
//   hits     (kHitBinding):        accel::Hit[capacity]  the CPU tracer writes, hit shading reads
//   counters (kRayCounterBinding): uint[2]               [0] rays in the list, [1] reflective pixels;
//            GPU atomics in device memory, copied into a slot of a readback ring (one slot per frame
//            in flight, gl/readback_ring.h) by finish_ray_list() or request_counts()
// std430 lays `struct { vec3 origin; float t_min; vec3 direction; float t_max; }` out exactly as
// accel::Ray (32 bytes) and `struct { float t; uint instance, prim; float u, v; }` as accel::Hit
// (20 bytes), so the CPU tracer reads and writes the mapped memory in place.
#include "accel/ray.h"
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace glint::render {

struct RayListCounts {
  std::uint32_t rays = 0;        // rays the ray-list pass wrote
  std::uint32_t reflective = 0;  // reflective pixels it saw (rays == reflective in rt mode)
};

enum class RayHitMemory { host_mapped, device };

class RayHitBuffers {
public:
  // Needs a current GL context; throws glint::Error for capacity 0.
  explicit RayHitBuffers(std::size_t capacity, RayHitMemory memory = RayHitMemory::host_mapped);
  RayHitBuffers(const RayHitBuffers&) = delete;  // owns mapped pointers
  RayHitBuffers& operator=(const RayHitBuffers&) = delete;

  // Zeroes the device counters (before the ray-list pass).
  void reset_counters();
  // Binds rays, pixels, hits and counters to their storage bindings.
  void bind() const;

  // After the ray-list pass was issued: makes its writes visible to the CPU, copies the counters to
  // readback slot `slot` (< kFramesInFlight), waits for the GPU (a fence; glint::Error if it fails
  // or the GPU stalls for a minute) and returns them. The rays are readable through rays() afterwards.
  RayListCounts finish_ray_list(std::size_t slot);

  // The same in two halves, for GPU backends, whose frame must not wait for the counters:
  // request_counts() queues their copy into `slot` behind the GL work issued so far (and a fence);
  // requested_counts() reads them once the GPU is past it (waiting when `wait`; else nullopt when
  // they are not there yet). glint::Error for a slot never requested, or counts beyond the capacity.
  void request_counts(std::size_t slot);
  std::optional<RayListCounts> requested_counts(std::size_t slot, bool wait);

  // host_mapped only: the first `count` rays / hits of the mapped buffers; glint::Error beyond the
  // capacity, or for device memory.
  std::span<const accel::Ray> rays(std::size_t count) const;
  std::span<accel::Hit> hits(std::size_t count);

  std::size_t capacity() const { return capacity_; }
  RayHitMemory memory() const { return memory_; }
  GLuint pixel_buffer() const { return pixels_.id(); }
  // For sharing with CUDA (device memory).
  GLuint ray_buffer() const { return rays_.id(); }
  GLuint hit_buffer() const { return hits_.id(); }
  GLuint counter_buffer() const { return counters_.id(); }

private:
  std::size_t capacity_;
  RayHitMemory memory_;
  GlBuffer rays_, pixels_, hits_, counters_;
  ReadbackRing counts_readback_;
  accel::Ray* mapped_rays_ = nullptr;
  accel::Hit* mapped_hits_ = nullptr;
};

}  // namespace glint::render
