// SSIM against an independent, deliberately naive implementation (a full 11x11 window per output
// pixel, no separability), plus the properties the definition implies.
#include "metrics/ssim.h"

#include "metrics/metric_test_images.h"
#include "support/error_of.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numeric>

namespace glint::metrics {
namespace {

using glint::testing::error_of;
using glint::testing::random_plane;
using glint::testing::random_rgba8;

// Wang et al. 2004 written out directly: 2-D Gaussian window built and normalised in 2-D, every
// 'valid' window position visited, moments summed over the whole window, variances taken about the
// window mean. Shares no code with the library.
Plane reference_ssim_map(const Plane& a, const Plane& b) {
  constexpr int radius = 5, side = 11;
  constexpr double sigma = 1.5, c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double window[side][side];
  double window_sum = 0.0;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const double dx = i - radius, dy = j - radius;
      window[j][i] = std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
      window_sum += window[j][i];
    }
  for (auto& row : window)
    for (double& w : row) w /= window_sum;

  Plane map(a.width - side + 1, a.height - side + 1);
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      double mu_a = 0, mu_b = 0;
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
          mu_a += window[j][i] * a.at(x + i, y + j);
          mu_b += window[j][i] * b.at(x + i, y + j);
        }
      double var_a = 0, var_b = 0, cov = 0;
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
          const double da = a.at(x + i, y + j) - mu_a, db = b.at(x + i, y + j) - mu_b;
          var_a += window[j][i] * da * da;
          var_b += window[j][i] * db * db;
          cov += window[j][i] * da * db;
        }
      map.at(x, y) = ((2 * mu_a * mu_b + c1) * (2 * cov + c2)) / ((mu_a * mu_a + mu_b * mu_b + c1) * (var_a + var_b + c2));
    }
  return map;
}

double mean_of(const Plane& plane) {
  return std::accumulate(plane.pixels.begin(), plane.pixels.end(), 0.0) / static_cast<double>(plane.pixels.size());
}

Plane plus_noise(const Plane& base, const Plane& unit_noise, double amplitude) {
  Plane out = base;
  for (std::size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] += amplitude * unit_noise.pixels[i];
  return out;
}

TEST(Ssim, GaussianTapsAreNormalisedSymmetricAndHaveSigmaOnePointFive) {
  const std::vector<double> taps = ssim_gaussian_taps();
  ASSERT_EQ(taps.size(), 11u);
  EXPECT_NEAR(std::accumulate(taps.begin(), taps.end(), 0.0), 1.0, 1e-15);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(taps[i], taps[10 - i]);
  EXPECT_NEAR(taps[6] / taps[5], std::exp(-1.0 / (2 * 1.5 * 1.5)), 1e-15);
  EXPECT_NEAR(taps[0] / taps[5], std::exp(-25.0 / (2 * 1.5 * 1.5)), 1e-15);
}

TEST(Ssim, MatchesTheNaiveWindowImplementationOnRandomImages) {
  struct Case { int width, height; unsigned seed; double noise; };
  for (const Case& c : {Case{11, 11, 20, 30.0}, Case{17, 23, 21, 8.0}, Case{40, 31, 22, 60.0}, Case{12, 29, 23, 1.0}}) {
    const Plane reference = random_plane(c.width, c.height, c.seed, 0.0, 255.0);
    const Plane test = plus_noise(reference, random_plane(c.width, c.height, c.seed + 100, -1.0, 1.0), c.noise);
    const SsimResult result = ssim(test, reference);
    const Plane expected = reference_ssim_map(test, reference);
    ASSERT_EQ(result.map.width, expected.width);
    ASSERT_EQ(result.map.height, expected.height);
    for (std::size_t i = 0; i < expected.pixels.size(); ++i)
      ASSERT_NEAR(result.map.pixels[i], expected.pixels[i], 1e-6) << c.width << "x" << c.height << " at " << i;
    EXPECT_NEAR(result.mean, mean_of(expected), 1e-6);
  }
}

TEST(Ssim, MatchesTheNaiveImplementationOnUnrelatedImages) {
  const Plane a = random_plane(25, 19, 30, 0.0, 255.0), b = random_plane(25, 19, 31, 0.0, 255.0);
  const SsimResult result = ssim(a, b);
  const Plane expected = reference_ssim_map(a, b);
  for (std::size_t i = 0; i < expected.pixels.size(); ++i) ASSERT_NEAR(result.map.pixels[i], expected.pixels[i], 1e-6);
  EXPECT_LT(result.mean, 0.2);  // independent noise has almost no structure in common
}

TEST(Ssim, MapCoversTheValidWindowsOnly) {
  const Plane a = random_plane(30, 20, 32, 0.0, 255.0);
  const SsimResult result = ssim(a, a);
  EXPECT_EQ(result.map.width, 20);
  EXPECT_EQ(result.map.height, 10);
}

TEST(Ssim, IdenticalImagesScoreExactlyOne) {
  const ImageRgba8 image = random_rgba8(48, 33, 33);
  const ColourSsim s = colour_ssim(image, image);
  EXPECT_EQ(s.luma, 1.0);
  for (double channel : s.channel) EXPECT_EQ(channel, 1.0);
  const Plane luma = luma_plane(image);
  const SsimResult result = ssim(luma, luma);
  for (double value : result.map.pixels) ASSERT_EQ(value, 1.0);
}

TEST(Ssim, DecreasesMonotonicallyWithNoiseAmplitude) {
  const Plane base = random_plane(64, 48, 34, 40.0, 215.0);
  const Plane noise = random_plane(64, 48, 35, -1.0, 1.0);
  double previous = ssim(base, base).mean;
  EXPECT_EQ(previous, 1.0);
  for (double amplitude : {1.0, 2.0, 5.0, 10.0, 20.0, 40.0, 80.0, 160.0}) {
    const double value = ssim(plus_noise(base, noise, amplitude), base).mean;
    EXPECT_LT(value, previous) << "amplitude " << amplitude;
    previous = value;
  }
}

TEST(Ssim, ConstantShiftOfAConstantImageIsTheLuminanceTermOnly) {
  // Flat windows have zero variance, so the contrast-structure term is C2 / C2 = 1 and SSIM is
  // (2 a b + C1) / (a^2 + b^2 + C1).
  const double c1 = (0.01 * 255) * (0.01 * 255);
  for (double a : {0.0, 40.0, 128.0, 250.0})
    for (double shift : {1.0, 5.0, -20.0, 100.0}) {
      if (a + shift < 0.0) continue;
      const double b = a + shift;
      const double expected = (2 * a * b + c1) / (a * a + b * b + c1);
      const SsimResult result = ssim(Plane(16, 14, b), Plane(16, 14, a));
      for (double value : result.map.pixels) ASSERT_NEAR(value, expected, 1e-9) << a << " + " << shift;
      EXPECT_NEAR(result.mean, expected, 1e-9);
      EXPECT_LT(result.mean, 1.0);
    }
}

TEST(Ssim, ColourSsimUsesRec709LumaAndEachChannel) {
  // Constant images: luma 0.2126 * 200 + 0.7152 * 100 + 0.0722 * 50 against a grey of 100.
  const ImageRgba8 test(20, 20, {200, 100, 50, 255}), reference(20, 20, {100, 100, 100, 255});
  const double c1 = (0.01 * 255) * (0.01 * 255);
  auto luminance_term = [&](double x, double y) { return (2 * x * y + c1) / (x * x + y * y + c1); };
  const ColourSsim s = colour_ssim(test, reference);
  EXPECT_NEAR(s.luma, luminance_term(0.2126 * 200 + 0.7152 * 100 + 0.0722 * 50, 100.0), 1e-9);
  EXPECT_NEAR(s.channel[0], luminance_term(200, 100), 1e-9);
  EXPECT_NEAR(s.channel[1], 1.0, 1e-12);
  EXPECT_NEAR(s.channel[2], luminance_term(50, 100), 1e-9);
}

TEST(Ssim, ResultDoesNotDependOnTheNumberOfThreads) {
  const Plane a = random_plane(300, 200, 38, 0.0, 255.0);
  const Plane b = plus_noise(a, random_plane(300, 200, 39, -1.0, 1.0), 30.0);
  const SsimResult parallel = ssim(a, b);
  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const SsimResult serial = ssim(a, b);
  EXPECT_EQ(parallel.mean, serial.mean);
  EXPECT_EQ(parallel.map.pixels, serial.map.pixels);
}

TEST(Ssim, IsSymmetricInItsArguments) {
  const Plane a = random_plane(21, 21, 36, 0.0, 255.0);
  const Plane b = plus_noise(a, random_plane(21, 21, 37, -1.0, 1.0), 25.0);
  EXPECT_NEAR(ssim(a, b).mean, ssim(b, a).mean, 1e-12);
}

TEST(Ssim, ImagesSmallerThanTheWindowAreAnError) {
  const std::string message = error_of([] { ssim(Plane(10, 30), Plane(10, 30), {}, "a.png", "b.png"); });
  EXPECT_NE(message.find("a.png"), std::string::npos) << message;
  EXPECT_NE(message.find("10x30"), std::string::npos) << message;
  EXPECT_NE(message.find("11x11"), std::string::npos) << message;
}

TEST(Ssim, SizeMismatchIsAnErrorNamingBothSizes) {
  const std::string message = error_of([] { ssim(Plane(12, 12), Plane(13, 12), {}, "a.png", "b.png"); });
  EXPECT_EQ(message, "cannot compare 'a.png' (12x12) with reference 'b.png' (13x12): the sizes differ");
}

TEST(Ssim, InvalidOptionsAreErrors) {
  SsimOptions options;
  options.sigma = 0.0;
  EXPECT_NE(error_of([&] { ssim(Plane(12, 12), Plane(12, 12), options); }).find("sigma"), std::string::npos);
  options = {};
  options.k2 = 0.0;
  EXPECT_NE(error_of([&] { ssim(Plane(12, 12), Plane(12, 12), options); }).find("K2"), std::string::npos);
}

}  // namespace
}  // namespace glint::metrics
