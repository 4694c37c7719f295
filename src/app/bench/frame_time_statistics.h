#pragma once
// The numbers `glint bench` reports for a series of frame times: means over consecutive intervals of
// measured frames (the paper plots "intervals of 10 frames", Sec. V), and the mean, median and
// 5th/95th percentiles of the whole series, which unlike the mean are not dragged by a few slow
// frames (a rebuild spike, the OS taking a core).
#include <cstddef>
#include <span>
#include <vector>

namespace glint::bench {

struct IntervalMean {
  int first_frame = 0;    // walkthrough frame of the interval's first measured frame
  int last_frame = 0;     // ... and of its last
  std::size_t count = 0;  // measured frames in the interval
  double mean_ms = 0.0;
};

// Groups the series into runs of `interval` consecutive measured frames (the last run may be
// shorter) and averages each. With --stride 1 these are the paper's 10-frame intervals; with
// --stride K an interval spans 10 K walkthrough frames. glint::Error when the spans differ in size
// or `interval` is 0.
std::vector<IntervalMean> interval_means(std::span<const int> frames, std::span<const double> milliseconds,
                                         std::size_t interval);

// The p-th percentile (0 <= p <= 100) with linear interpolation between the closest ranks (numpy's
// default, Hyndman & Fan type 7): sorted values x_0..x_{n-1}, rank r = p / 100 * (n - 1),
// x_floor(r) + (r - floor(r)) * (x_ceil(r) - x_floor(r)). glint::Error for no values or p outside [0, 100].
double percentile(std::span<const double> values, double p);

struct SeriesSummary {
  std::size_t count = 0;
  double mean = 0.0;
  double median = 0.0;  // percentile 50
  double p5 = 0.0;
  double p95 = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// glint::Error for an empty series.
SeriesSummary summarize(std::span<const double> values);

}  // namespace glint::bench
