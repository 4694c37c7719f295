#include "render/occlusion_buffers.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/persistent_buffer.h"

#include <string>

namespace glint::render {

namespace {

// Bytes of the answers: a Hit per ray (closest); any: a uint per ray on the GPU, a byte per ray on
// the CPU, rounded up to whole uints since shaders read uints.
std::size_t answer_bytes(std::size_t capacity, RayQuery query, bool device) {
  if (query == RayQuery::closest) return capacity * sizeof(accel::Hit);
  return device ? capacity * sizeof(std::uint32_t) : (capacity + 3) / 4 * 4;
}

}  // namespace

OcclusionBuffers::OcclusionBuffers(std::size_t capacity, rt::RayTracer& tracer, const char* what, RayQuery query)
    : capacity_(capacity),
      what_(what),
      query_(query),
      tracer_(&tracer),
      device_(tracer.device_tracing()),
      gl_(tracer.gl_tracing()) {
  if (capacity == 0) fail("{}: capacity must be at least one ray", what_);
  const auto count = static_cast<std::uint32_t>(capacity);
  ray_count_ = create_buffer(sizeof(count), &count, 0);
  if (device_ || gl_) {
    rays_ = create_buffer(capacity * sizeof(accel::Ray), nullptr, 0);
    occluded_ = create_buffer(answer_bytes(capacity, query, true), nullptr, 0);
  }
  if (device_) {
    const cuda::InteropBuffer shared[] = {{rays_.id(), cuda::InteropAccess::read_only},
                                          {occluded_.id(), cuda::InteropAccess::write_discard},
                                          {ray_count_.id(), cuda::InteropAccess::read_only}};
    interop_.emplace(shared);
  } else if (!gl_) {
    void* mapped = nullptr;
    rays_ = create_persistently_mapped_buffer(capacity * sizeof(accel::Ray), GL_MAP_READ_BIT, &mapped,
                                              (std::string(what) + ": rays").c_str());
    mapped_rays_ = static_cast<accel::Ray*>(mapped);
    occluded_ = create_persistently_mapped_buffer(answer_bytes(capacity, query, false), GL_MAP_WRITE_BIT, &mapped,
                                                  (std::string(what) + ": answers").c_str());
    mapped_occluded_ = static_cast<std::uint8_t*>(mapped);
    ray_fence_.emplace(1, sizeof(count), what);
  }
  check_gl(what);
}

void OcclusionBuffers::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowRayBinding, rays_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kShadowOcclusionBinding, occluded_.id());
}

void OcclusionBuffers::trace(std::size_t host_count, GLuint gl_count) {
  start_trace(host_count, gl_count);
  finish_trace();
}

void OcclusionBuffers::finish_trace() { held_map_.reset(); }

void OcclusionBuffers::start_trace(std::size_t host_count, GLuint gl_count) {
  if (held_map_) fail("{}: a trace started before the last one finished", what_);
  if (gl_) {  // GL dispatches, ordered after the pass that wrote the rays by GL itself
    const auto capacity = static_cast<std::uint32_t>(capacity_);
    const GLuint count = gl_count != 0 ? gl_count : ray_count_.id();
    if (query_ == RayQuery::closest)
      gl_->trace_closest_gl(rays_.id(), occluded_.id(), count, capacity);
    else
      gl_->trace_any_gl(rays_.id(), occluded_.id(), count, capacity);
    return;
  }
  if (device_) {
    // Mapping orders the CUDA stream after the pass that wrote the rays, unmapping (finish_trace)
    // orders the GL passes that read the answers after the trace. Nobody reads this trace's GPU
    // time: its ticket is let go.
    const cuda::ScopedInteropMap& mapped = held_map_.emplace(*interop_, device_->stream());
    const rt::GpuTicket ticket =
        query_ == RayQuery::closest
            ? device_->trace_closest_device(mapped.pointer<const accel::Ray>(0), mapped.pointer<accel::Hit>(1),
                                            mapped.pointer<const std::uint32_t>(2),
                                            static_cast<std::uint32_t>(capacity_))
            : device_->trace_any_device(mapped.pointer<const accel::Ray>(0), mapped.pointer<std::uint32_t>(1),
                                        mapped.pointer<const std::uint32_t>(2), static_cast<std::uint32_t>(capacity_));
    device_->drop_ticket(ticket);
    return;
  }
  if (host_count > capacity_) fail("{}: {} rays, more than the capacity {}", what_, host_count, capacity_);
  // The fence behind a 4-byte copy also makes the rays reach the coherent mapping (the ring's
  // barrier); the answers the CPU writes reach GL commands issued after them (coherent mapping).
  ray_fence_->copy_buffer(0, ray_count_.id(), sizeof(std::uint32_t));
  (void)ray_fence_->read(0, /*wait=*/true);
  if (query_ == RayQuery::closest)
    tracer_->trace_closest({mapped_rays_, host_count}, {reinterpret_cast<accel::Hit*>(mapped_occluded_), host_count});
  else
    tracer_->trace_any({mapped_rays_, host_count}, {mapped_occluded_, host_count});
}

cuda::ScopedInteropMap OcclusionBuffers::map_for_cuda() {
  if (!device_) fail("{}: a CPU backend's rays are not shared with CUDA", what_);
  return cuda::ScopedInteropMap(*interop_, device_->stream());
}

std::span<const accel::Ray> OcclusionBuffers::rays() const {
  if (mapped_rays_ == nullptr) fail("{}: the rays of a GPU backend stay in GPU memory", what_);
  return {mapped_rays_, capacity_};
}

std::span<const std::uint8_t> OcclusionBuffers::occluded() const {
  if (query_ != RayQuery::any) fail("{}: the answers are hits, not occlusion flags", what_);
  if (mapped_occluded_ == nullptr) fail("{}: the answers of a GPU backend stay in GPU memory", what_);
  return {mapped_occluded_, capacity_};
}

std::span<const accel::Hit> OcclusionBuffers::hits() const {
  if (query_ != RayQuery::closest) fail("{}: the answers are occlusion flags, not hits", what_);
  if (mapped_occluded_ == nullptr) fail("{}: the hits of a GPU backend stay in GPU memory", what_);
  return {reinterpret_cast<const accel::Hit*>(mapped_occluded_), capacity_};
}

}  // namespace glint::render
