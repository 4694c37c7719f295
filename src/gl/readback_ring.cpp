#include "gl/readback_ring.h"

#include "core/error.h"
#include "gl/gl_check.h"

#include <chrono>
#include <cstdint>
#include <utility>

namespace glint {

ReadbackRing::ReadbackRing(std::size_t slots, std::size_t slot_bytes, std::string what)
    : what_(std::move(what)), slot_bytes_(slot_bytes), fences_(slots, nullptr), filled_(slots, false) {
  if (slots == 0 || slot_bytes == 0) fail("{}: a readback ring needs at least one slot of one byte", what_);
  constexpr GLbitfield kMapped = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  // GL_CLIENT_STORAGE_BIT asks for host memory: the CPU reads every byte.
  buffer_ = create_buffer(slots * slot_bytes, nullptr, kMapped | GL_CLIENT_STORAGE_BIT);
  mapped_ = static_cast<const std::byte*>(
      glMapNamedBufferRange(buffer_.id(), 0, static_cast<GLsizeiptr>(slots * slot_bytes), kMapped));
  if (mapped_ == nullptr) fail("{}: could not map the readback buffer ({} bytes) persistently", what_, slots * slot_bytes);
  check_gl("readback ring: create");
}

ReadbackRing::~ReadbackRing() { release(); }

ReadbackRing::ReadbackRing(ReadbackRing&& other) noexcept
    : what_(std::move(other.what_)),
      slot_bytes_(other.slot_bytes_),
      buffer_(std::move(other.buffer_)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      fences_(std::move(other.fences_)),
      filled_(std::move(other.filled_)) {
  other.fences_.clear();
}

ReadbackRing& ReadbackRing::operator=(ReadbackRing&& other) noexcept {
  if (this != &other) {
    release();
    what_ = std::move(other.what_);
    slot_bytes_ = other.slot_bytes_;
    buffer_ = std::move(other.buffer_);
    mapped_ = std::exchange(other.mapped_, nullptr);
    fences_ = std::move(other.fences_);
    filled_ = std::move(other.filled_);
    other.fences_.clear();
  }
  return *this;
}

void ReadbackRing::release() {
  for (GLsync& fence : fences_)
    if (fence != nullptr) glDeleteSync(std::exchange(fence, nullptr));
}

std::size_t ReadbackRing::checked_slot(std::size_t slot) const {
  if (slot >= fences_.size()) fail("{}: slot {} of a ring of {}", what_, slot, fences_.size());
  return slot;
}

void ReadbackRing::fence(std::size_t slot) {
  GLsync& fence = fences_[slot];
  if (fence != nullptr) glDeleteSync(fence);
  fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (fence == nullptr) fail("{}: glFenceSync failed", what_);
  filled_[slot] = true;
}

void ReadbackRing::copy_buffer(std::size_t slot, GLuint source, std::size_t bytes) {
  checked_slot(slot);
  if (bytes > slot_bytes_) fail("{}: {} bytes do not fit a slot of {}", what_, bytes, slot_bytes_);
  // Shader writes (atomics) must reach the copy; the copy's writes reach the coherent mapping by the fence.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
  glCopyNamedBufferSubData(source, buffer_.id(), 0, static_cast<GLintptr>(slot * slot_bytes_),
                           static_cast<GLsizeiptr>(bytes));
  check_gl("readback ring: copy");
  fence(slot);
}

void ReadbackRing::capture_texture(std::size_t slot, GLuint texture, GLenum format, GLenum type, std::size_t bytes) {
  checked_slot(slot);
  if (bytes > slot_bytes_) fail("{}: {} bytes do not fit a slot of {}", what_, bytes, slot_bytes_);
  glMemoryBarrier(GL_PIXEL_BUFFER_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
  // With a pack buffer bound, the "pixels" pointer is an offset into it.
  glGetTextureImage(texture, 0, format, type, static_cast<GLsizei>(bytes),
                    reinterpret_cast<void*>(static_cast<std::uintptr_t>(slot * slot_bytes_)));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  check_gl("readback ring: texture capture");
  fence(slot);
}

bool ReadbackRing::ready(std::size_t slot) {
  GLsync& fence = fences_[checked_slot(slot)];
  if (fence == nullptr) return filled_[slot];
  // The flush bit makes sure the fence reaches the GPU at all; a timeout of 0 never waits.
  const GLenum status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
  if (status == GL_WAIT_FAILED) fail("{}: glClientWaitSync failed", what_);
  if (status == GL_TIMEOUT_EXPIRED) return false;
  glDeleteSync(std::exchange(fence, nullptr));
  return true;
}

std::span<const std::byte> ReadbackRing::read(std::size_t slot, bool wait) {
  GLsync& fence = fences_[checked_slot(slot)];
  if (!filled_[slot]) fail("{}: slot {} read before anything was copied into it", what_, slot);
  if (fence != nullptr) {
    if (!wait && !ready(slot)) return {};
    if (fence != nullptr) {
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
      GLenum status = GL_TIMEOUT_EXPIRED;
      while (status == GL_TIMEOUT_EXPIRED && std::chrono::steady_clock::now() < give_up)
        status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, 100'000'000);  // 100 ms per wait
      if (status == GL_WAIT_FAILED) fail("{}: waiting for the GPU failed (glClientWaitSync)", what_);
      if (status == GL_TIMEOUT_EXPIRED) fail("{}: the GPU did not finish within a minute", what_);
      glDeleteSync(std::exchange(fence, nullptr));
    }
  }
  return {mapped_ + slot * slot_bytes_, slot_bytes_};
}

}  // namespace glint
