#pragma once
// glint's one wall-clock timer for host work (builds, updates, traces, whole runs): started when made,
// read in milliseconds. GPU work is timed with GPU queries or CUDA events instead (gl/gpu_timer.h,
// cuda/gpu_span_pool.h). Header-only (glint_accel uses it too).
#include <chrono>

namespace glint {

class Stopwatch {
public:
  using Clock = std::chrono::steady_clock;

  Stopwatch() : start_(Clock::now()) {}

  // Milliseconds since construction or the last restart().
  double elapsed_ms() const { return std::chrono::duration<double, std::milli>(Clock::now() - start_).count(); }

  void restart() { start_ = Clock::now(); }

  // elapsed_ms(), then restart(): consecutive phases timed with one watch.
  double lap_ms() {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_).count();
    start_ = now;
    return ms;
  }

private:
  Clock::time_point start_;
};

}  // namespace glint
