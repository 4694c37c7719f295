#include "render/ray_hit_buffers.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/render_targets.h"

#include <array>
#include <chrono>

namespace glint::render {
namespace {

constexpr GLbitfield kPersistent = GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

// A buffer with immutable storage mapped for the whole of its life (unmapped when deleted).
// GL_CLIENT_STORAGE_BIT asks for host memory: the CPU touches every byte each frame.
GlBuffer create_mapped_buffer(std::size_t bytes, GLbitfield access, void** mapped, const char* what) {
  GlBuffer buffer = create_buffer(bytes, nullptr, access | kPersistent | GL_CLIENT_STORAGE_BIT);
  *mapped = glMapNamedBufferRange(buffer.id(), 0, static_cast<GLsizeiptr>(bytes), access | kPersistent);
  if (*mapped == nullptr) fail("ray buffers: could not map the {} buffer ({} bytes) persistently", what, bytes);
  return buffer;
}

}  // namespace

RayHitBuffers::RayHitBuffers(std::size_t capacity, RayHitMemory memory) : capacity_(capacity), memory_(memory) {
  if (capacity == 0) fail("ray buffers: capacity must be at least one ray");
  void* mapped = nullptr;
  if (memory == RayHitMemory::host_mapped) {
    rays_ = create_mapped_buffer(capacity * sizeof(accel::Ray), GL_MAP_READ_BIT, &mapped, "ray");
    mapped_rays_ = static_cast<accel::Ray*>(mapped);
    hits_ = create_mapped_buffer(capacity * sizeof(accel::Hit), GL_MAP_WRITE_BIT, &mapped, "hit");
    mapped_hits_ = static_cast<accel::Hit*>(mapped);
  } else {
    rays_ = create_buffer(capacity * sizeof(accel::Ray), nullptr, 0);
    hits_ = create_buffer(capacity * sizeof(accel::Hit), nullptr, 0);
  }
  counters_readback_ = create_mapped_buffer(2 * sizeof(std::uint32_t), GL_MAP_READ_BIT, &mapped, "counter");
  mapped_counters_ = static_cast<const std::uint32_t*>(mapped);
  pixels_ = create_buffer(capacity * sizeof(std::uint32_t), nullptr, 0);
  counters_ = create_buffer(2 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  check_gl("ray buffers: create");
}

RayHitBuffers::~RayHitBuffers() {
  if (counts_fence_ != nullptr) glDeleteSync(counts_fence_);
}

void RayHitBuffers::reset_counters() {
  const std::array<std::uint32_t, 2> zero{0, 0};
  glNamedBufferSubData(counters_.id(), 0, sizeof(zero), zero.data());
}

void RayHitBuffers::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRayBinding, rays_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRayPixelBinding, pixels_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kHitBinding, hits_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRayCounterBinding, counters_.id());
}

RayListCounts RayHitBuffers::finish_ray_list() {
  request_counts();
  return read_requested_counts();
}

void RayHitBuffers::request_counts() {
  // Shader writes to a persistently mapped buffer reach the CPU only after this barrier and a fence.
  glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glCopyNamedBufferSubData(counters_.id(), counters_readback_.id(), 0, 0, 2 * sizeof(std::uint32_t));
  if (counts_fence_ != nullptr) glDeleteSync(counts_fence_);
  counts_fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (counts_fence_ == nullptr) fail("ray buffers: glFenceSync failed");
}

RayListCounts RayHitBuffers::read_requested_counts() {
  GLsync fence = counts_fence_;
  if (fence == nullptr) fail("ray buffers: counters read without request_counts()");
  counts_fence_ = nullptr;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  GLenum status = GL_TIMEOUT_EXPIRED;
  while (status == GL_TIMEOUT_EXPIRED && std::chrono::steady_clock::now() < give_up)
    status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 100'000'000);  // 100 ms per wait
  glDeleteSync(fence);
  if (status == GL_WAIT_FAILED) fail("ray buffers: waiting for the ray list failed (glClientWaitSync)");
  if (status == GL_TIMEOUT_EXPIRED) fail("ray buffers: the GPU did not finish the ray list within a minute");
  check_gl("ray buffers: read counters");
  RayListCounts counts{mapped_counters_[0], mapped_counters_[1]};
  if (counts.rays > capacity_)
    fail("ray buffers: the ray list reports {} rays, more than its capacity {}", counts.rays, capacity_);
  return counts;
}

std::span<const accel::Ray> RayHitBuffers::rays(std::size_t count) const {
  if (memory_ != RayHitMemory::host_mapped) fail("ray buffers: rays in device memory cannot be read by the CPU");
  if (count > capacity_) fail("ray buffers: {} rays asked of a list of capacity {}", count, capacity_);
  return {mapped_rays_, count};
}

std::span<accel::Hit> RayHitBuffers::hits(std::size_t count) {
  if (memory_ != RayHitMemory::host_mapped) fail("ray buffers: hits in device memory cannot be written by the CPU");
  if (count > capacity_) fail("ray buffers: {} hits asked of a list of capacity {}", count, capacity_);
  return {mapped_hits_, count};
}

}  // namespace glint::render
