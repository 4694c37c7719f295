#include "metrics/ssim.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace glint::metrics {
namespace {

// The five Gaussian-weighted local moments SSIM is made of: E[x], E[y], E[x^2], E[y^2], E[xy].
struct LocalMoments {
  Plane x, y, xx, yy, xy;
};

void check_options(const SsimOptions& options) {
  if (options.window_radius < 0) fail("SSIM: window radius must be >= 0, got {}", options.window_radius);
  if (!(options.sigma > 0.0)) fail("SSIM: Gaussian sigma must be > 0, got {}", options.sigma);
  // C1 and C2 keep the ratio defined on flat, black windows; without them it can divide by zero.
  if (!(options.k1 > 0.0) || !(options.k2 > 0.0)) fail("SSIM: K1 and K2 must be > 0, got {} and {}", options.k1, options.k2);
  if (!(options.dynamic_range > 0.0)) fail("SSIM: dynamic range L must be > 0, got {}", options.dynamic_range);
}

// First pass of the separable window: along each row, keeping only positions where all taps lie
// inside the row. The products x*x, y*y, x*y are formed here, before any filtering, as E[.] needs.
LocalMoments filter_rows(const Plane& a, const Plane& b, const std::vector<double>& taps) {
  const int tap_count = static_cast<int>(taps.size());
  const int out_width = a.width - tap_count + 1;
  LocalMoments m{Plane(out_width, a.height), Plane(out_width, a.height), Plane(out_width, a.height),
                 Plane(out_width, a.height), Plane(out_width, a.height)};
  tbb::parallel_for(tbb::blocked_range<int>(0, a.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const double* row_a = &a.at(0, y);
      const double* row_b = &b.at(0, y);
      for (int x = 0; x < out_width; ++x) {
        double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
        for (int k = 0; k < tap_count; ++k) {
          const double w = taps[static_cast<std::size_t>(k)];
          const double va = row_a[x + k], vb = row_b[x + k];
          sx += w * va;
          sy += w * vb;
          sxx += w * va * va;
          syy += w * vb * vb;
          sxy += w * va * vb;
        }
        m.x.at(x, y) = sx;
        m.y.at(x, y) = sy;
        m.xx.at(x, y) = sxx;
        m.yy.at(x, y) = syy;
        m.xy.at(x, y) = sxy;
      }
    }
  });
  return m;
}

// Second pass: along each column, again 'valid' positions only.
Plane filter_columns(const Plane& in, const std::vector<double>& taps) {
  const int tap_count = static_cast<int>(taps.size());
  Plane out(in.width, in.height - tap_count + 1);
  tbb::parallel_for(tbb::blocked_range<int>(0, out.height), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      double* out_row = &out.at(0, y);
      // Tap-major order walks rows of `in` contiguously; each output still sums its taps in order.
      for (int k = 0; k < tap_count; ++k) {
        const double w = taps[static_cast<std::size_t>(k)];
        const double* in_row = &in.at(0, y + k);
        for (int x = 0; x < out.width; ++x) out_row[x] += w * in_row[x];
      }
    }
  });
  return out;
}

}  // namespace

std::vector<double> ssim_gaussian_taps(const SsimOptions& options) {
  check_options(options);
  const int r = options.window_radius;
  std::vector<double> taps(static_cast<std::size_t>(2 * r + 1));
  double sum = 0.0;
  for (int i = -r; i <= r; ++i) {
    const double value = std::exp(-static_cast<double>(i * i) / (2.0 * options.sigma * options.sigma));
    taps[static_cast<std::size_t>(i + r)] = value;
    sum += value;
  }
  for (double& tap : taps) tap /= sum;
  return taps;
}

SsimResult ssim(const Plane& test, const Plane& reference, const SsimOptions& options, std::string_view test_name,
                std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  const std::vector<double> taps = ssim_gaussian_taps(options);
  const int side = static_cast<int>(taps.size());
  if (test.width < side || test.height < side)
    fail("cannot compute SSIM of '{}' and '{}': the images are {}x{}, smaller than the {}x{} window", test_name,
         reference_name, test.width, test.height, side, side);

  const LocalMoments rows = filter_rows(test, reference, taps);
  const LocalMoments m{filter_columns(rows.x, taps), filter_columns(rows.y, taps), filter_columns(rows.xx, taps),
                       filter_columns(rows.yy, taps), filter_columns(rows.xy, taps)};

  const double c1 = (options.k1 * options.dynamic_range) * (options.k1 * options.dynamic_range);
  const double c2 = (options.k2 * options.dynamic_range) * (options.k2 * options.dynamic_range);
  SsimResult result;
  result.map = Plane(m.x.width, m.x.height);
  std::vector<double> row_sums(static_cast<std::size_t>(result.map.height), 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, result.map.height), [&](const tbb::blocked_range<int>& range) {
    for (int y = range.begin(); y < range.end(); ++y) {
      double row_sum = 0.0;
      for (int x = 0; x < result.map.width; ++x) {
        const double mu_x = m.x.at(x, y), mu_y = m.y.at(x, y);
        const double var_x = m.xx.at(x, y) - mu_x * mu_x;
        const double var_y = m.yy.at(x, y) - mu_y * mu_y;
        const double cov_xy = m.xy.at(x, y) - mu_x * mu_y;
        // Identical inputs make numerator and denominator the same floating-point value (doubling
        // is exact), so identical images score exactly 1.
        const double numerator = (2.0 * mu_x * mu_y + c1) * (2.0 * cov_xy + c2);
        const double denominator = (mu_x * mu_x + mu_y * mu_y + c1) * (var_x + var_y + c2);
        const double value = numerator / denominator;
        result.map.at(x, y) = value;
        row_sum += value;
      }
      row_sums[static_cast<std::size_t>(y)] = row_sum;
    }
  });
  // Rows are summed in order so the mean does not depend on how TBB split the work.
  double total = 0.0;
  for (double row_sum : row_sums) total += row_sum;
  result.mean = total / static_cast<double>(result.map.pixels.size());
  return result;
}

ColourSsim colour_ssim(const ImageRgba8& test, const ImageRgba8& reference, const SsimOptions& options,
                       std::string_view test_name, std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  ColourSsim result;
  result.luma = ssim(luma_plane(test), luma_plane(reference), options, test_name, reference_name).mean;
  for (Channel c : kColourChannels)
    result.channel[static_cast<std::size_t>(c)] =
        ssim(channel_plane(test, c), channel_plane(reference, c), options, test_name, reference_name).mean;
  return result;
}

}  // namespace glint::metrics
