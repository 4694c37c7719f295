#include "render/reflection_cost_model.h"

#include <algorithm>
#include <cmath>

namespace glint::render {
namespace {

void fold(double& estimate, std::uint64_t& samples, double sample) {
  estimate = samples == 0 ? sample : estimate + ReflectionCostModel::kSmoothing * (sample - estimate);
  ++samples;
}

}  // namespace

ReflectionCosts prior_reflection_costs(bool device_tracing) {
  // Orders of magnitude only (H100 cuda: SSR ~4 ns per pixel, a ray ~5 ns with its list and shading;
  // llvmpipe + cpu backend at 640x360: SSR ~1 us per pixel, a ray ~1 us); the first frames replace them.
  return device_tracing ? ReflectionCosts{4e-6, 5e-6} : ReflectionCosts{1e-3, 1e-3};
}

void AffineCostFit::add(double items, double ms) {
  w_ = kDecay * w_ + 1.0;
  n_ = kDecay * n_ + items;
  t_ = kDecay * t_ + ms;
  nn_ = kDecay * nn_ + items * items;
  nt_ = kDecay * nt_ + items * ms;
}

std::optional<double> AffineCostFit::slope() const {
  if (w_ <= 0.0) return std::nullopt;
  const double mean_n = n_ / w_, mean_t = t_ / w_;
  const double var_n = nn_ / w_ - mean_n * mean_n;
  const double deviation = std::sqrt(std::max(0.0, var_n));
  if (deviation < std::max(0.1 * mean_n, static_cast<double>(kMinCostSampleWork))) return std::nullopt;
  const double cov = nt_ / w_ - mean_n * mean_t;
  return std::max(0.0, cov / var_n);
}

ReflectionCostModel::ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionCosts> fixed)
    : average_(prior), fixed_(fixed) {}

void ReflectionCostModel::observe(const CostSample& sample) {
  if (sample.ssr_ms > 0.0) {
    ssr_fit_.add(sample.ssr_pixels, sample.ssr_ms);
    if (sample.ssr_pixels >= kMinCostSampleWork)
      fold(average_.ms_per_ssr_pixel, ssr_samples_, sample.ssr_ms / sample.ssr_pixels);
  }
  if (sample.ray_ms > 0.0) {
    ray_fit_.add(sample.rays, sample.ray_ms);
    if (sample.rays >= kMinCostSampleWork) fold(average_.ms_per_ray, ray_samples_, sample.ray_ms / sample.rays);
  }
}

ReflectionCosts ReflectionCostModel::costs() const {
  if (fixed_) return *fixed_;
  return {ssr_fit_.slope().value_or(average_.ms_per_ssr_pixel), ray_fit_.slope().value_or(average_.ms_per_ray)};
}

}  // namespace glint::render
