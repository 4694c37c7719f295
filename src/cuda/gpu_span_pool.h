#pragma once
// GPU times of enqueued work, read when the GPU has done it. Each timed span gets a ticket (a running
// number) and a Span (start/stop events, and whatever the caller keeps beside them) from a pool; the
// time is read with the ticket, frames later, after a GL fence said the frame that enqueued the span
// is done, so reading it never waits for the GPU and never holds back the frames in flight.
//
// A span is kept until its time is read or the caller lets it go (release): reading it is what frees
// it, however many spans came after it, and a freed Span is reused by a later one. So the pool holds
// at most the spans not yet read, and no caller needs to know a capacity. (It was a ring of 64 event
// pairs reused round-robin: a frame of many reflection samples, two spans a sample, reused the slot of
// the frame's structure update before the update's time was read.) A span's time is read once; a
// ticket never issued, or asked again after it was read or let go, is a glint::Error naming it.
//
// Plain C++ over any Span type, so its bookkeeping is tested without a GPU (tests/cuda/
// gpu_span_pool_test.cpp); cuda/cuda_span.h is the CUDA Span. Span: default-constructible, and
//   std::optional<double> elapsed_ms(bool wait)  // nullopt while the GPU has not reached the stop
//                                                // and `wait` is false
// Spans never move (a deque): work in flight may refer to a Span's memory.
#include "cuda/cuda_errors.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace glint::cuda {

template <typename Span>
class GpuSpanPool {
public:
  // `what` names the timed work in errors ("rt cuda").
  explicit GpuSpanPool(const char* what) : what_(what) {}

  // A span for new work: a freed Span if there is one (its previous work was read, or let go; one
  // stream orders the new work after it), else a new one. The caller records its events.
  std::uint64_t open() {
    std::size_t index = spans_.size();
    if (free_.empty()) {
      spans_.emplace_back();
    } else {
      index = free_.back();
      free_.pop_back();
    }
    held_.emplace(next_, index);
    return next_++;
  }

  // The Span of a held ticket; glint::Error for one never issued, read or let go.
  Span& span(std::uint64_t ticket) { return spans_[index_of(ticket)]; }
  bool holds(std::uint64_t ticket) const { return held_.count(ticket) != 0; }

  // The span's time in milliseconds; nullopt (the span kept) while the GPU has not reached its stop
  // and `wait` is false. A time read frees the span, after `on_time(span)` looked at what was kept
  // beside its events.
  template <typename OnTime>
  std::optional<double> read_ms(std::uint64_t ticket, bool wait, OnTime&& on_time) {
    Span& read = span(ticket);
    const std::optional<double> ms = read.elapsed_ms(wait);
    if (!ms) return std::nullopt;
    std::forward<OnTime>(on_time)(read);
    release(ticket);
    return ms;
  }
  std::optional<double> read_ms(std::uint64_t ticket, bool wait) {
    return read_ms(ticket, wait, [](const Span&) {});
  }
  // The time without freeing the span (a second reader will still ask for it).
  std::optional<double> peek_ms(std::uint64_t ticket, bool wait) { return span(ticket).elapsed_ms(wait); }

  // Frees the span unread: its time will not be asked for.
  void release(std::uint64_t ticket) {
    free_.push_back(index_of(ticket));
    held_.erase(ticket);
  }

  std::uint64_t issued() const { return next_; }  // tickets handed out so far
  std::size_t held() const { return held_.size(); }  // spans not yet read or let go
  std::size_t pooled() const { return spans_.size(); }  // Spans made: the most ever held at once

private:
  std::size_t index_of(std::uint64_t ticket) const {
    const auto found = held_.find(ticket);
    if (found != held_.end()) return found->second;
    if (ticket >= next_)
      fail_message(std::string(what_) + ": GPU time of span " + std::to_string(ticket) + " asked, but " +
                   std::to_string(next_) + " spans were started");
    fail_message(std::string(what_) + ": GPU time of span " + std::to_string(ticket) +
                 " asked after it was read or let go (a span's time is read once)");
  }

  const char* what_;
  std::deque<Span> spans_;
  std::vector<std::size_t> free_;  // indices of spans_ not held
  std::unordered_map<std::uint64_t, std::size_t> held_;  // ticket -> index of spans_
  std::uint64_t next_ = 0;
};

}  // namespace glint::cuda
