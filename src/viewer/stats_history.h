#pragma once
// The last frames' measurements for the Stats panel: per-pass GPU times and the frame time as rolling
// series (oldest first, at most kHistoryFrames each), plus the latest counts.
#include "app/frame_loop.h"

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint::viewer {

inline constexpr std::size_t kHistoryFrames = 240;

class StatsHistory {
public:
  // Adds one rendered frame; `wall_ms` is the time since the previous frame was shown (for FPS).
  void add(const FrameMeasurement& measured, double wall_ms);

  // Pass name -> its times, oldest first; a pass that did not run in a frame counts 0 there.
  const std::map<std::string, std::vector<float>>& pass_series() const { return passes_; }
  const std::vector<float>& gpu_total_series() const { return gpu_total_; }
  double frames_per_second() const;  // over the kept frames' wall times; 0 before two frames
  const std::optional<FrameMeasurement>& last() const { return last_; }
  void clear();

private:
  std::map<std::string, std::vector<float>> passes_;
  std::vector<float> gpu_total_;
  std::deque<double> wall_ms_;
  std::optional<FrameMeasurement> last_;
};

}  // namespace glint::viewer
