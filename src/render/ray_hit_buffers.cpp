#include "render/ray_hit_buffers.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/persistent_buffer.h"
#include "render/render_targets.h"

#include <array>
#include <cstring>

namespace glint::render {

RayHitBuffers::RayHitBuffers(std::size_t capacity, RayHitMemory memory)
    : capacity_(capacity), memory_(memory), counts_readback_(kFramesInFlight, 2 * sizeof(std::uint32_t), "ray counters") {
  if (capacity == 0) fail("ray buffers: capacity must be at least one ray");
  void* mapped = nullptr;
  if (memory == RayHitMemory::host_mapped) {
    rays_ = create_persistently_mapped_buffer(capacity * sizeof(accel::Ray), GL_MAP_READ_BIT, &mapped,
                                              "ray buffers: rays");
    mapped_rays_ = static_cast<accel::Ray*>(mapped);
    hits_ = create_persistently_mapped_buffer(capacity * sizeof(accel::Hit), GL_MAP_WRITE_BIT, &mapped,
                                              "ray buffers: hits");
    mapped_hits_ = static_cast<accel::Hit*>(mapped);
  } else {
    rays_ = create_buffer(capacity * sizeof(accel::Ray), nullptr, 0);
    hits_ = create_buffer(capacity * sizeof(accel::Hit), nullptr, 0);
  }
  pixels_ = create_buffer(capacity * sizeof(std::uint32_t), nullptr, 0);
  counters_ = create_buffer(2 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  check_gl("ray buffers: create");
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

RayListCounts RayHitBuffers::finish_ray_list(std::size_t slot) {
  request_counts(slot);
  return *requested_counts(slot, /*wait=*/true);
}

void RayHitBuffers::request_counts(std::size_t slot) {
  // The ring's copy comes after a barrier that also makes the ray list's shader writes reach the
  // persistently mapped rays, and its fence covers both.
  counts_readback_.copy_buffer(slot, counters_.id(), 2 * sizeof(std::uint32_t));
}

std::optional<RayListCounts> RayHitBuffers::requested_counts(std::size_t slot, bool wait) {
  const std::span<const std::byte> bytes = counts_readback_.read(slot, wait);
  if (bytes.empty()) return std::nullopt;
  std::array<std::uint32_t, 2> values{0, 0};
  std::memcpy(values.data(), bytes.data(), sizeof(values));
  const RayListCounts counts{values[0], values[1]};
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
