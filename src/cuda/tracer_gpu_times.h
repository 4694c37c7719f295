#pragma once
// How a GPU ray tracer's (cuda, optix) timed work is read: the rt::DeviceTracing rules of gpu_ms,
// drop_ticket and last_update, and stats()'s last update time, written once for both backends over
// a GpuSpanPool (one ticket space for traces and structure updates).
//   - A trace's ticket goes to its caller, who reads its time (gpu_ms) or lets it go (drop_ticket);
//     its span is kept until then, however many spans come after.
//   - An update's ticket is handed out by take_last_update() (DeviceTracing::last_update): whoever
//     takes it reads it, and its span is kept until then (a frame loop reads each frame's update
//     frames later, after the next frames' updates and their traces). An update nobody took is let
//     go at the next update or when the last update's time is known.
//   - The last update's time stays readable (stats(), and a second read of its ticket) until the
//     next update: it is kept here once read.
// Plain C++ over any Span (gpu_span_pool.h), tested with fake spans (tests/cuda/gpu_span_pool_test.cpp).
#include "cuda/gpu_span_pool.h"

#include <cstdint>
#include <optional>
#include <utility>

namespace glint::cuda {

template <typename Span>
class TracerGpuTimes {
public:
  explicit TracerGpuTimes(const char* what) : spans_(what) {}

  // A span for a trace or an update (then say so with opened_update); the caller records its events.
  std::uint64_t open() { return spans_.open(); }
  Span& span(std::uint64_t ticket) { return spans_.span(ticket); }

  // `ticket` (just opened) is the structure's new update: the previous one is let go unless its
  // ticket was taken and not read yet.
  void opened_update(std::uint64_t ticket) {
    forget_update();
    last_update_ = ticket;
  }
  // No update since (a new build): stats report none.
  void forget_update() {
    if (last_update_ && !taken_ && spans_.holds(*last_update_)) spans_.release(*last_update_);
    last_update_.reset();
    taken_ = false;
    last_update_ms_.reset();
  }

  // The last update's ticket, for the caller to read (DeviceTracing::last_update).
  std::optional<std::uint64_t> take_last_update() {
    if (last_update_) taken_ = true;
    return last_update_;
  }

  // DeviceTracing::gpu_ms: the time of `ticket`'s work, its span freed once read (`on_time(span)`
  // first: what the work found, kept beside its events). The last update's time is kept for a
  // second read.
  template <typename OnTime>
  std::optional<double> read_ms(std::uint64_t ticket, bool wait, OnTime&& on_time) {
    if (ticket == last_update_ && last_update_ms_) {
      if (spans_.holds(ticket)) spans_.release(ticket);  // taken, read here first by stats()
      return last_update_ms_;
    }
    const std::optional<double> ms = spans_.read_ms(ticket, wait, std::forward<OnTime>(on_time));
    if (ms && ticket == last_update_) last_update_ms_ = ms;
    return ms;
  }
  std::optional<double> read_ms(std::uint64_t ticket, bool wait) {
    return read_ms(ticket, wait, [](const Span&) {});
  }

  // DeviceTracing::drop_ticket: the caller will not read `ticket`.
  void drop(std::uint64_t ticket) {
    if (ticket == last_update_) {
      // Still the last update: kept for stats(), let go at the next update.
      spans_.span(ticket);  // glint::Error where it was read or let go already
      taken_ = false;
      if (last_update_ms_) spans_.release(ticket);
      return;
    }
    spans_.release(ticket);
  }

  // stats()'s last_update_ms: the last update's GPU time (waits for it), 0 without an update.
  double last_update_ms() {
    if (!last_update_) return 0.0;
    if (!last_update_ms_) {
      last_update_ms_ = spans_.peek_ms(*last_update_, /*wait=*/true);
      // Nobody holds its ticket: the time is all that is left to ask for.
      if (!taken_) spans_.release(*last_update_);
    }
    return *last_update_ms_;
  }

  const GpuSpanPool<Span>& spans() const { return spans_; }

private:
  GpuSpanPool<Span> spans_;
  std::optional<std::uint64_t> last_update_;
  bool taken_ = false;  // take_last_update handed out last_update_
  std::optional<double> last_update_ms_;  // last_update_'s time once read
};

}  // namespace glint::cuda
