#pragma once
// GL buffers shared with CUDA (cudaGraphicsGLRegisterBuffer): registered once, mapped around the
// CUDA work of each frame. Mapping on a stream orders that stream after the GL commands issued
// before it, and unmapping orders later GL commands after the stream's work, so GL and CUDA hand
// buffers to each other on the GPU without the host waiting or copying anything.
// Plain C++ (no CUDA or GL headers); a build without CUDA throws at construction.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace glint::cuda {

// How CUDA uses a buffer, so the driver can skip needless synchronisation or copies.
enum class InteropAccess { read_only, write_discard, read_write };

struct InteropBuffer {
  std::uint32_t gl_buffer = 0;  // GL buffer name (GLuint)
  InteropAccess access = InteropAccess::read_write;
};

class GlBufferInterop {
public:
  // Needs the GL context that owns the buffers to be current, on the GPU CUDA uses;
  // glint::Error naming the buffer when registration fails (e.g. GL runs on another device).
  explicit GlBufferInterop(std::span<const InteropBuffer> buffers);
  ~GlBufferInterop();
  GlBufferInterop(const GlBufferInterop&) = delete;
  GlBufferInterop& operator=(const GlBufferInterop&) = delete;

  // Maps every buffer on `stream` (a cudaStream_t) and returns their device pointers, in the
  // constructor's order. Call unmap() before GL uses them again.
  std::vector<void*> map(void* stream);
  void unmap(void* stream);

  // GL-CUDA-GL round trips since the process started: maps made while no GlBufferInterop was mapped
  // (a map inside another's mapping shares its round trip, if its unmap waits for the outer one's
  // CUDA work too). Each costs about 0.3 ms of an H100 frame (docs/perf.md "Seventh round"): the GPU
  // switching between GL's work and CUDA's, not a wait of the host's ("Ninth round"); tests
  // count them per frame. GL runs on one thread, so a plain counter does.
  static std::uint64_t round_trips();

private:
  struct Resources;
  std::unique_ptr<Resources> resources_;
  bool mapped_ = false;
};

// Maps on construction and unmaps on destruction (also when the CUDA work in between throws).
class ScopedInteropMap {
public:
  ScopedInteropMap(GlBufferInterop& interop, void* stream) : interop_(interop), stream_(stream) {
    pointers_ = interop_.map(stream_);
  }
  ~ScopedInteropMap() {
    try {
      interop_.unmap(stream_);
    } catch (...) {  // an unmap failure after another error must not terminate; the first error wins
    }
  }
  ScopedInteropMap(const ScopedInteropMap&) = delete;
  ScopedInteropMap& operator=(const ScopedInteropMap&) = delete;

  template <typename T>
  T* pointer(std::size_t index) const {
    return static_cast<T*>(pointers_.at(index));
  }

private:
  GlBufferInterop& interop_;
  void* stream_;
  std::vector<void*> pointers_;
};

}  // namespace glint::cuda
