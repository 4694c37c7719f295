#pragma once
// GPU times of enqueued CUDA work, read when the GPU has done it. Each timed span gets a ticket (a
// running number) and one of `slots` start/stop event pairs, reused round-robin; the time is read
// with the ticket, frames later, after a GL fence said the frame that enqueued the span is done, so
// reading it never waits for the GPU and never holds back the frames in flight (one pair of events
// per backend did both: the next span overwrote the pair, so each had to be read before the next
// began, and a frame's second trace hid its first). A ticket whose slot was reused since is an error
// naming both numbers. CUDA runtime header: include it from .cu files and src/optix/ only.
#include "cuda/cuda_stream_events.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint::cuda {

class GpuTimeRing {
public:
  // `what` names the timed work in errors ("rt cuda trace"). 64 slots hold 3 frames in flight of
  // many spans each.
  explicit GpuTimeRing(const char* what, std::size_t slots = 64) : what_(what), slots_(slots) {}

  // Records the span's start on `stream` and returns its ticket; stop() records its end.
  std::uint64_t start(cudaStream_t stream) {
    const std::uint64_t ticket = next_++;
    slots_[slot_of(ticket)].start.record(stream);
    return ticket;
  }
  void stop(std::uint64_t ticket, cudaStream_t stream) { slots_[checked_slot(ticket)].stop.record(stream); }

  // Milliseconds from the span's start to its stop; nullopt while the GPU has not reached the stop
  // and `wait` is false. glint::Error for a ticket never issued or whose slot was reused.
  std::optional<double> elapsed_ms(std::uint64_t ticket, bool wait) const {
    const Slot& slot = slots_[checked_slot(ticket)];
    if (!wait) {
      const cudaError_t status = cudaEventQuery(slot.stop.get());
      if (status == cudaErrorNotReady) {
        cudaGetLastError();  // a not-ready query is not an error; clear it
        return std::nullopt;
      }
      GLINT_CUDA_CHECK(status);
    }
    return cuda::elapsed_ms(slot.start, slot.stop);
  }

  // The slot `ticket` uses (for data kept beside its events); glint::Error as elapsed_ms.
  std::size_t slot(std::uint64_t ticket) const { return checked_slot(ticket); }

  // Whether `ticket` was issued and its slot not reused since.
  bool holds(std::uint64_t ticket) const { return ticket < next_ && next_ - ticket <= slots_.size(); }

private:
  struct Slot {
    CudaEvent start, stop;
  };
  std::size_t slot_of(std::uint64_t ticket) const { return static_cast<std::size_t>(ticket % slots_.size()); }
  std::size_t checked_slot(std::uint64_t ticket) const {
    if (!holds(ticket))
      fail_message(std::string(what_) + ": GPU time of span " + std::to_string(ticket) + " asked after " +
                   std::to_string(next_) + " spans (the last " + std::to_string(slots_.size()) + " are kept)");
    return slot_of(ticket);
  }

  const char* what_;
  std::vector<Slot> slots_;
  std::uint64_t next_ = 0;
};

}  // namespace glint::cuda
