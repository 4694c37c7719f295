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
  const double mean_n = n_ / w_, mean_t = t_ / w_;
  const double var_n = nn_ / w_ - mean_n * mean_n;
  const double deviation = std::sqrt(std::max(0.0, var_n));
  // Points that all did about the same work say nothing new about the slope: keep the last one.
  if (deviation < std::max(0.1 * mean_n, static_cast<double>(kMinCostSampleWork))) return;
  slope_ = std::max(0.0, (nt_ / w_ - mean_n * mean_t) / var_n);
}

std::optional<CostLine> AffineCostFit::line() const {
  if (!slope_ || w_ <= 0.0) return std::nullopt;
  const double mean_n = n_ / w_, mean_t = t_ / w_;
  const double fixed = mean_t - *slope_ * mean_n;
  // A negative fixed part (noise, or a slope from other times) would make the line undershoot small
  // work and overshoot this: the line through the origin and the points' mean instead.
  if (fixed < 0.0) return CostLine{0.0, mean_n > 0.0 ? mean_t / mean_n : *slope_};
  return CostLine{fixed, *slope_};
}

ReflectionCostModel::ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionStageCosts> fixed)
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
  if (sample.classify_ms > 0.0) fold(classify_ms_, classify_samples_, sample.classify_ms);
}

ReflectionCosts ReflectionCostModel::costs() const { return stage_costs().marginal; }

ReflectionStageCosts ReflectionCostModel::stage_costs() const {
  if (fixed_) return *fixed_;
  ReflectionStageCosts stages;
  stages.marginal = average_;
  if (const std::optional<CostLine> ssr = ssr_fit_.line()) {
    stages.marginal.ms_per_ssr_pixel = ssr->per_item_ms;
    stages.ssr_fixed_ms = ssr->fixed_ms;
  }
  if (const std::optional<CostLine> ray = ray_fit_.line()) {
    stages.marginal.ms_per_ray = ray->per_item_ms;
    stages.ray_fixed_ms = ray->fixed_ms;
  }
  stages.classify_ms = classify_ms_;
  return stages;
}

}  // namespace glint::render
