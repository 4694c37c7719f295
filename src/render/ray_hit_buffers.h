#pragma once
// The buffers through which rays and hit records move between GL and a ray tracer, created once at
// a capacity of one ray per pixel, so a frame allocates nothing. Two kinds of memory:
//  - host (CPU backends): the rays are copied to host memory after the ray-list pass
//    (glGetNamedBufferSubData, which waits for the pass) and the tracer's hits are copied back
//    (glNamedBufferSubData) before hit shading. Both copies are ordered by GL itself. An earlier
//    version let the tracer read and write persistently mapped, coherent buffers in place; on Mesa's
//    llvmpipe with more than one thread, hit shading then read some hits before the CPU's writes
//    reached it and frames differed from run to run (docs/reliability.md). The copies cost about
//    52 bytes per ray, far less than tracing the ray on the CPU;
//  - device (GPU backends): rays and hits stay in GPU memory, shared with CUDA (GlBufferInterop),
//    and the counters are read back only after the frame, for statistics.
//   rays     (kRayBinding):        accel::Ray[capacity]  the ray-list pass writes, the tracer reads
//   pixels   (kRayPixelBinding):   uint[capacity]        y * width + x of ray i; GPU only
//   hits     (kHitBinding):        accel::Hit[capacity]  the tracer writes, hit shading reads
//   counters (kRayCounterBinding): uint[2]               [0] rays in the list, [1] reflective pixels;
//            GPU atomics in device memory, copied to a mapped readback buffer by request_counts()
// std430 lays `struct { vec3 origin; float t_min; vec3 direction; float t_max; }` out exactly as
// accel::Ray (32 bytes) and `struct { float t; uint instance, prim; float u, v; }` as accel::Hit
// (20 bytes), so both copy byte for byte.
#include "accel/ray.h"
#include "gl/gl_objects.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glint::render {

struct RayListCounts {
  std::uint32_t rays = 0;        // rays the ray-list pass wrote
  std::uint32_t reflective = 0;  // reflective pixels it saw (rays == reflective in rt mode)
};

enum class RayHitMemory { host, device };

class RayHitBuffers {
public:
  // Needs a current GL context; throws glint::Error for capacity 0.
  explicit RayHitBuffers(std::size_t capacity, RayHitMemory memory = RayHitMemory::host);
  ~RayHitBuffers();
  RayHitBuffers(const RayHitBuffers&) = delete;  // owns a fence and a mapped pointer
  RayHitBuffers& operator=(const RayHitBuffers&) = delete;

  // Zeroes the device counters (before the ray-list pass).
  void reset_counters();
  // Binds rays, pixels, hits and counters to their storage bindings.
  void bind() const;

  // After the ray-list pass was issued: copies the counters to the readback buffer, waits for the GPU
  // (a fence; glint::Error if it fails or the GPU stalls for a minute) and returns them.
  RayListCounts finish_ray_list();

  // The same in two halves, for GPU backends, whose frame must not wait for the counters:
  // request_counts() queues their copy behind the GL work issued so far (and a fence);
  // read_requested_counts() waits for that fence and returns them. glint::Error without a request.
  void request_counts();
  RayListCounts read_requested_counts();

  // host only: the first `count` rays of the list, copied to host memory (after finish_ray_list());
  // then the tracer's `hits` for them, copied to the GPU for hit shading. glint::Error beyond the
  // capacity, or for device memory.
  std::span<const accel::Ray> read_rays(std::size_t count);
  void write_hits(std::span<const accel::Hit> hits);
  // A host array of `count` hits for the tracer to fill (reused from frame to frame).
  std::span<accel::Hit> host_hits(std::size_t count);

  std::size_t capacity() const { return capacity_; }
  RayHitMemory memory() const { return memory_; }
  GLuint pixel_buffer() const { return pixels_.id(); }
  // For sharing with CUDA (device memory).
  GLuint ray_buffer() const { return rays_.id(); }
  GLuint hit_buffer() const { return hits_.id(); }
  GLuint counter_buffer() const { return counters_.id(); }

private:
  void require_host(std::size_t count, const char* what) const;

  std::size_t capacity_;
  RayHitMemory memory_;
  GLsync counts_fence_ = nullptr;  // set by request_counts()
  GlBuffer rays_, pixels_, hits_, counters_, counters_readback_;
  std::vector<accel::Ray> host_rays_;  // host memory only, `capacity_` entries
  std::vector<accel::Hit> host_hits_;
  const std::uint32_t* mapped_counters_ = nullptr;
};

}  // namespace glint::render
