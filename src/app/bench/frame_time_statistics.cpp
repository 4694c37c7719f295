#include "app/bench/frame_time_statistics.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace glint::bench {

std::vector<IntervalMean> interval_means(std::span<const int> frames, std::span<const double> milliseconds,
                                         std::size_t interval) {
  if (frames.size() != milliseconds.size())
    fail("interval means: {} frames but {} times", frames.size(), milliseconds.size());
  if (interval == 0) fail("interval means: the interval must hold at least one frame");
  std::vector<IntervalMean> means;
  for (std::size_t first = 0; first < frames.size(); first += interval) {
    const std::size_t end = std::min(first + interval, frames.size());
    IntervalMean mean;
    mean.first_frame = frames[first];
    mean.last_frame = frames[end - 1];
    mean.count = end - first;
    mean.mean_ms = std::accumulate(milliseconds.begin() + static_cast<std::ptrdiff_t>(first),
                                   milliseconds.begin() + static_cast<std::ptrdiff_t>(end), 0.0) /
                   static_cast<double>(mean.count);
    means.push_back(mean);
  }
  return means;
}

double percentile(std::span<const double> values, double p) {
  if (values.empty()) fail("percentile of no values");
  if (!(p >= 0.0 && p <= 100.0)) fail("percentile {} is outside [0, 100]", p);
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (rank - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

SeriesSummary summarize(std::span<const double> values) {
  if (values.empty()) fail("summary of an empty series");
  SeriesSummary summary;
  summary.count = values.size();
  summary.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  summary.median = percentile(values, 50.0);
  summary.p5 = percentile(values, 5.0);
  summary.p95 = percentile(values, 95.0);
  const auto [min, max] = std::minmax_element(values.begin(), values.end());
  summary.min = *min;
  summary.max = *max;
  return summary;
}

}  // namespace glint::bench
