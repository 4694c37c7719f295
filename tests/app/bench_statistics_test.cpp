// glint bench's frame-time statistics: interval means against a hand computation, percentiles
// against numpy's linear interpolation, and the summary's order invariants.
#include "app/bench/frame_time_statistics.h"

#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace glint::bench {
namespace {

TEST(BenchStatistics, IntervalMeansAverageConsecutiveMeasuredFrames) {
  const std::vector<int> frames = {0, 3, 6, 9, 12, 15, 18};
  const std::vector<double> ms = {1, 2, 3, 10, 20, 30, 7};
  const std::vector<IntervalMean> means = interval_means(frames, ms, 3);
  ASSERT_EQ(means.size(), 3u) << "two full intervals and a short last one";
  EXPECT_EQ(means[0].first_frame, 0);
  EXPECT_EQ(means[0].last_frame, 6);
  EXPECT_EQ(means[0].count, 3u);
  EXPECT_DOUBLE_EQ(means[0].mean_ms, 2.0);
  EXPECT_EQ(means[1].first_frame, 9);
  EXPECT_EQ(means[1].last_frame, 15);
  EXPECT_DOUBLE_EQ(means[1].mean_ms, 20.0);
  EXPECT_EQ(means[2].first_frame, 18);
  EXPECT_EQ(means[2].last_frame, 18);
  EXPECT_EQ(means[2].count, 1u);
  EXPECT_DOUBLE_EQ(means[2].mean_ms, 7.0);
}

TEST(BenchStatistics, IntervalMeansKeepTheOverallMeanOfFullIntervals) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> time(5.0, 50.0);
  std::vector<int> frames(100);
  std::vector<double> ms(100);
  for (int i = 0; i < 100; ++i) {
    frames[static_cast<std::size_t>(i)] = i;
    ms[static_cast<std::size_t>(i)] = time(random);
  }
  const std::vector<IntervalMean> means = interval_means(frames, ms, 10);
  ASSERT_EQ(means.size(), 10u);
  double sum_of_means = 0.0;
  for (const IntervalMean& mean : means) sum_of_means += mean.mean_ms;
  EXPECT_NEAR(sum_of_means / 10.0, std::accumulate(ms.begin(), ms.end(), 0.0) / 100.0, 1e-9);
}

TEST(BenchStatistics, IntervalMeansRejectMismatchedInput) {
  const std::vector<int> frames = {0, 1};
  const std::vector<double> ms = {1.0};
  EXPECT_NE(testing::error_of([&] { (void)interval_means(frames, ms, 10); }).find("2 frames but 1 times"),
            std::string::npos);
  const std::vector<double> two = {1.0, 2.0};
  EXPECT_NE(testing::error_of([&] { (void)interval_means(frames, two, 0); }).find("at least one frame"),
            std::string::npos);
}

TEST(BenchStatistics, PercentilesInterpolateBetweenRanksLikeNumpy) {
  const std::vector<double> values = {15, 20, 35, 40, 50};  // unsorted input is sorted first
  std::vector<double> shuffled = {40, 15, 50, 35, 20};
  EXPECT_DOUBLE_EQ(percentile(shuffled, 0.0), 15.0);
  EXPECT_DOUBLE_EQ(percentile(shuffled, 100.0), 50.0);
  EXPECT_DOUBLE_EQ(percentile(shuffled, 50.0), 35.0);
  // numpy.percentile([15, 20, 35, 40, 50], [5, 40, 95]) = [16, 29, 48]
  EXPECT_DOUBLE_EQ(percentile(values, 5.0), 16.0);
  EXPECT_DOUBLE_EQ(percentile(values, 40.0), 29.0);
  EXPECT_DOUBLE_EQ(percentile(values, 95.0), 48.0);
  const std::vector<double> even = {1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(percentile(even, 50.0), 2.5) << "the median of an even count is the mean of the middle two";
  const std::vector<double> one = {7};
  EXPECT_DOUBLE_EQ(percentile(one, 95.0), 7.0);
}

TEST(BenchStatistics, PercentileRejectsEmptyInputAndBadRanks) {
  const std::vector<double> none;
  EXPECT_NE(testing::error_of([&] { (void)percentile(none, 50.0); }).find("no values"), std::string::npos);
  const std::vector<double> some = {1, 2};
  EXPECT_NE(testing::error_of([&] { (void)percentile(some, 101.0); }).find("outside [0, 100]"), std::string::npos);
}

TEST(BenchStatistics, SummaryIsOrderedAndMatchesItsDefinitions) {
  std::mt19937 random(9);
  std::exponential_distribution<double> time(0.1);
  std::vector<double> ms(257);
  for (double& value : ms) value = 5.0 + time(random);
  const SeriesSummary summary = summarize(ms);
  EXPECT_EQ(summary.count, ms.size());
  EXPECT_DOUBLE_EQ(summary.min, *std::min_element(ms.begin(), ms.end()));
  EXPECT_DOUBLE_EQ(summary.max, *std::max_element(ms.begin(), ms.end()));
  EXPECT_NEAR(summary.mean, std::accumulate(ms.begin(), ms.end(), 0.0) / 257.0, 1e-9);
  std::vector<double> sorted = ms;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_DOUBLE_EQ(summary.median, sorted[128]) << "an odd count's median is its middle value";
  EXPECT_LE(summary.min, summary.p5);
  EXPECT_LE(summary.p5, summary.median);
  EXPECT_LE(summary.median, summary.p95);
  EXPECT_LE(summary.p95, summary.max);
  EXPECT_GT(summary.mean, summary.median) << "a right-skewed series' mean lies above its median";
}

}  // namespace
}  // namespace glint::bench
