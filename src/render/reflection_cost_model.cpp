#include "render/reflection_cost_model.h"

namespace glint::render {
namespace {

void fold(double& estimate, std::uint64_t& samples, double sample) {
  estimate = samples == 0 ? sample : estimate + ReflectionCostModel::kSmoothing * (sample - estimate);
  ++samples;
}

}  // namespace

ReflectionCosts prior_reflection_costs(bool device_tracing) {
  // Orders of magnitude only (H100 cuda: SSR ~4 ns per pixel, a ray ~5 ns with its list and shading;
  // llvmpipe + cpu backend at 640x360: SSR ~0.3 us per pixel, a ray ~3 us); the first frames replace them.
  return device_tracing ? ReflectionCosts{4e-6, 5e-6} : ReflectionCosts{3e-4, 3e-3};
}

ReflectionCostModel::ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionCosts> fixed)
    : costs_(prior), fixed_(fixed) {}

void ReflectionCostModel::observe(const CostSample& sample) {
  if (sample.ssr_pixels >= kMinCostSampleWork && sample.ssr_ms > 0.0)
    fold(costs_.ms_per_ssr_pixel, ssr_samples_, sample.ssr_ms / sample.ssr_pixels);
  if (sample.rays >= kMinCostSampleWork && sample.ray_ms > 0.0)
    fold(costs_.ms_per_ray, ray_samples_, sample.ray_ms / sample.rays);
}

}  // namespace glint::render
