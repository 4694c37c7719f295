#include "viewer/stats_history.h"

#include <numeric>

namespace glint::viewer {
namespace {

void push(std::vector<float>& series, float value) {
  series.push_back(value);
  if (series.size() > kHistoryFrames) series.erase(series.begin());
}

}  // namespace

void StatsHistory::add(const FrameMeasurement& measured, double wall_ms) {
  std::map<std::string, float> frame;
  float total = 0.0f;
  for (const PassTime& pass : measured.times.passes) {
    frame[pass.name] += static_cast<float>(pass.milliseconds);
    total += static_cast<float>(pass.milliseconds);
  }
  // Every series keeps one value per frame, so the graphs stay aligned.
  const std::size_t frames = gpu_total_.size();
  for (const auto& [name, ms] : frame)
    if (!passes_.contains(name)) passes_[name] = std::vector<float>(frames, 0.0f);
  for (auto& [name, series] : passes_) push(series, frame.contains(name) ? frame[name] : 0.0f);
  push(gpu_total_, total);
  if (wall_ms > 0.0) {
    wall_ms_.push_back(wall_ms);
    if (wall_ms_.size() > kHistoryFrames) wall_ms_.pop_front();
  }
  last_ = measured;
  last_->final_image.reset();  // kept elsewhere; the stats need the numbers only
}

double StatsHistory::frames_per_second() const {
  if (wall_ms_.empty()) return 0.0;
  const double total = std::accumulate(wall_ms_.begin(), wall_ms_.end(), 0.0);
  return total > 0.0 ? 1000.0 * static_cast<double>(wall_ms_.size()) / total : 0.0;
}

void StatsHistory::clear() { *this = StatsHistory(); }

}  // namespace glint::viewer
