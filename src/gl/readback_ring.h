#pragma once
// A few slots of GPU -> CPU readback, one per frame in flight, so a frame's results (counters, the
// final image) are copied on the GPU behind the frame's own work and read by the CPU frames later,
// without stalling the pipeline. Each slot is `slot_bytes` of one persistently mapped, coherent
// host buffer (GL_PIXEL_PACK_BUFFER for texture captures, a copy target for buffers) and a fence
// placed after its copy. read() looks at the fence: a slot is read only once the GPU has passed it
// (ready()), or when the caller must wait (the ring wrapped, end of a run).
//
//   ReadbackRing counts(kFramesInFlight, 2 * sizeof(std::uint32_t), "ssr counters");
//   counts.copy_buffer(frame % kFramesInFlight, counter_buffer);         // inside frame N
//   ...
//   auto bytes = counts.read(slot, /*wait=*/true);                      // frames later
#include "gl/gl_objects.h"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace glint {

// Frames a pipelined run keeps on the GPU at once (submitted, results not read yet); every ring of
// per-frame results has this many slots.
inline constexpr std::size_t kFramesInFlight = 3;

class ReadbackRing {
public:
  // Needs a current GL context; `what` names the ring in errors.
  ReadbackRing(std::size_t slots, std::size_t slot_bytes, std::string what);
  ~ReadbackRing();
  ReadbackRing(const ReadbackRing&) = delete;  // owns fences and a mapping
  ReadbackRing& operator=(const ReadbackRing&) = delete;
  ReadbackRing(ReadbackRing&& other) noexcept;
  ReadbackRing& operator=(ReadbackRing&& other) noexcept;

  // Queues a copy of `bytes` bytes from `source` (a buffer) into `slot` behind the GL work issued so
  // far, and fences it. Shader writes to `source` must be made visible to buffer copies first
  // (GL_BUFFER_UPDATE_BARRIER_BIT); this does that.
  void copy_buffer(std::size_t slot, GLuint source, std::size_t bytes);
  // Queues level 0 of `texture` into `slot` as `format`/`type` (glGetTextureImage into the pack
  // buffer; rows bottom first, tightly packed) and fences it. glint::Error when it does not fit.
  void capture_texture(std::size_t slot, GLuint texture, GLenum format, GLenum type, std::size_t bytes);

  // Whether the GPU has finished the slot's last copy (never waits). False for a slot never filled.
  bool ready(std::size_t slot);
  // The slot's bytes once its copy finished: waits for it when `wait` (glint::Error if the GPU
  // stalls for a minute), else returns an empty span when it is not ready. The span stays valid
  // until the slot is filled again. glint::Error for a slot never filled.
  std::span<const std::byte> read(std::size_t slot, bool wait);

  std::size_t slots() const { return fences_.size(); }
  std::size_t slot_bytes() const { return slot_bytes_; }

private:
  std::size_t checked_slot(std::size_t slot) const;
  void fence(std::size_t slot);
  void release();

  std::string what_;
  std::size_t slot_bytes_ = 0;
  GlBuffer buffer_;
  const std::byte* mapped_ = nullptr;
  std::vector<GLsync> fences_;  // null: no copy pending (filled_ says whether it ever held one)
  std::vector<bool> filled_;
};

}  // namespace glint
