#include "render/tile_classification.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace glint::render {
namespace {

double tile_rays(const TileEvidence& tile, TileClass tile_class, float unknown_failure_rate,
                 const TileThresholds& thresholds) {
  const double reflective = tile.reflective;
  switch (tile_class) {
    case TileClass::rt_only: return reflective;
    case TileClass::ssr_fallback:
      return reflective * (known_enough(tile, thresholds) ? failure_rate(tile) : unknown_failure_rate);
    default: return 0.0;
  }
}

// The thresholds that minimise the cost of every tile at full quality (SSR only within the target).
TileThresholds cost_optimal(const ThresholdInputs& inputs) {
  TileThresholds thresholds;
  const double ssr = std::max(0.0, inputs.costs.ms_per_ssr_pixel), ray = std::max(0.0, inputs.costs.ms_per_ray);
  if (!(ssr > 0.0)) {  // SSR costs nothing more per pixel: SSR first, rays where it fails
    thresholds.ssr_only_at_most = inputs.max_unreflected_fraction;
    thresholds.rt_at_least = 1.0f;
    return thresholds;
  }
  // A ray that costs nothing more (a GPU whose trace time hardly grows with the rays) is the
  // cheapest choice everywhere, not a missing measurement.
  const double ratio = ray > 0.0 ? ssr / ray : std::numeric_limits<double>::infinity();
  // Rays alone cost R c_ray, SSR + rays R c_ssr + f R c_ray: rays alone from f = 1 - c_ssr / c_ray.
  thresholds.rt_at_least = static_cast<float>(std::clamp(1.0 - ratio, 0.0, 1.0));
  // SSR only saves rays only while SSR is the cheaper of the two per pixel.
  thresholds.ssr_only_at_most = ratio < 1.0 ? inputs.max_unreflected_fraction : -1.0f;
  return thresholds;
}

struct KnownTile {
  float f;
  double reflective;
};

}  // namespace

bool known_enough(const TileEvidence& tile, const TileThresholds& thresholds) {
  return tile.known > 0 &&
         static_cast<float>(tile.known) >= thresholds.min_known_fraction * static_cast<float>(tile.reflective);
}

// In steps of 2^-16, by an integer division: the GLSL twin computes the same bits, where a float
// division would not (GLSL allows 2.5 ulp; NVIDIA's differed from the host's at 3/30).
float failure_rate(const TileEvidence& tile) {
  return static_cast<float>((tile.failed_known * 65536u) / tile.known) / 65536.0f;
}

TileClass classify_tile(const TileEvidence& tile, const TileThresholds& thresholds) {
  if (tile.reflective == 0) return TileClass::none;
  // Without history SSR + rays reflects the tile and learns its failure rate, unless rays win at any
  // failure rate (rt_at_least <= 0): then what SSR would say does not matter.
  if (!known_enough(tile, thresholds)) return thresholds.rt_at_least <= 0.0f ? TileClass::rt_only : TileClass::ssr_fallback;
  const float f = failure_rate(tile);
  if (f <= thresholds.ssr_only_at_most) return TileClass::ssr_only;
  if (f >= thresholds.rt_at_least) return TileClass::rt_only;
  return TileClass::ssr_fallback;
}

double expected_rays(std::span<const TileEvidence> tiles, const TileThresholds& thresholds,
                     float unknown_failure_rate) {
  double rays = 0.0;
  for (const TileEvidence& tile : tiles)
    rays += tile_rays(tile, classify_tile(tile, thresholds), unknown_failure_rate, thresholds);
  return rays;
}

TileThresholds choose_tile_thresholds(std::span<const TileEvidence> tiles, const ThresholdInputs& inputs) {
  TileThresholds thresholds = cost_optimal(inputs);
  if (!inputs.ray_budget) return thresholds;
  const double budget = std::max(0.0, *inputs.ray_budget);
  double rays = expected_rays(tiles, thresholds, inputs.unknown_failure_rate);
  if (rays <= budget) return thresholds;

  std::vector<KnownTile> known;
  for (const TileEvidence& tile : tiles)
    if (tile.reflective > 0 && known_enough(tile, thresholds) &&
        classify_tile(tile, thresholds) != TileClass::ssr_only)
      known.push_back({failure_rate(tile), static_cast<double>(tile.reflective)});
  std::sort(known.begin(), known.end(), [](const KnownTile& a, const KnownTile& b) { return a.f < b.f; });

  // 1. Rays-only tiles become SSR + rays, lowest f first: each saves (1 - f) R rays at no loss.
  for (std::size_t i = 0; i < known.size() && rays > budget;) {
    const float f = known[i].f;
    std::size_t end = i;
    double saved = 0.0;
    for (; end < known.size() && known[end].f == f; ++end)
      if (f >= thresholds.rt_at_least) saved += (1.0 - f) * known[end].reflective;
    if (f >= thresholds.rt_at_least) {
      rays -= saved;
      thresholds.rt_at_least = std::nextafter(f, 2.0f);
    }
    i = end;
  }
  // Tiles without history follow rt_at_least too (classify_tile): count again.
  rays = expected_rays(tiles, thresholds, inputs.unknown_failure_rate);
  if (rays <= budget) return thresholds;
  // 2. SSR + rays tiles become SSR only, lowest f first: each saves f R rays and leaves them unreflected.
  //    Tiles of one failure rate move together (a threshold cannot split them); a group whose move
  //    would leave the budget partly unspent stays, and the ray list's cap cuts what is over.
  for (std::size_t i = 0; i < known.size() && rays > budget;) {
    const float f = known[i].f;
    std::size_t end = i;
    double saved = 0.0;
    for (; end < known.size() && known[end].f == f; ++end) saved += f * known[end].reflective;
    if (rays - saved < budget) break;
    rays -= saved;
    thresholds.ssr_only_at_most = std::max(thresholds.ssr_only_at_most, f);
    i = end;
  }
  return thresholds;
}

double rays_within_ms(std::span<const TileEvidence> tiles, const ThresholdInputs& inputs, double budget_ms) {
  if (!(inputs.costs.ms_per_ray > 0.0)) return 0.0;
  const TileThresholds thresholds = cost_optimal(inputs);
  double ssr_pixels = 0.0;
  for (const TileEvidence& tile : tiles) {
    const TileClass tile_class = classify_tile(tile, thresholds);
    if (tile_class == TileClass::ssr_only || tile_class == TileClass::ssr_fallback) ssr_pixels += tile.reflective;
  }
  return std::max(0.0, (budget_ms - inputs.costs.ms_per_ssr_pixel * ssr_pixels) / inputs.costs.ms_per_ray);
}

}  // namespace glint::render
