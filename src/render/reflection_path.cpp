#include "render/reflection_path.h"

#include <algorithm>

namespace glint::render {

ReflectionPathCosts compare_reflection_paths(const ReflectionPathInputs& inputs) {
  const ReflectionStageCosts& costs = inputs.costs;
  const double ssr = std::max(0.0, costs.marginal.ms_per_ssr_pixel), ray = std::max(0.0, costs.marginal.ms_per_ray);

  double tiles_reflective = 0.0, ssr_pixels = 0.0, rays = 0.0, unknown = 0.0;
  for (const TileEvidence& tile : inputs.tiles) {
    if (tile.reflective == 0) continue;
    const double reflective = tile.reflective;
    tiles_reflective += reflective;
    if (!known_enough(tile, inputs.thresholds)) {
      unknown += reflective;
      continue;
    }
    switch (classify_tile(tile, inputs.thresholds)) {
      case TileClass::ssr_only: ssr_pixels += reflective; break;
      case TileClass::ssr_fallback:
        ssr_pixels += reflective;
        rays += failure_rate(tile) * reflective;
        break;
      case TileClass::rt_only: rays += reflective; break;
      case TileClass::none: break;
    }
  }
  // The tiles may be frames older than the pixel count (a whole-frame path classifies nothing):
  // their shares, at today's count. Without tiles every pixel is unknown.
  const double pixels = std::max(0.0, inputs.reflective_pixels);
  if (tiles_reflective > 0.0 && pixels > 0.0) {
    const double scale = pixels / tiles_reflective;
    ssr_pixels *= scale;
    rays *= scale;
    unknown *= scale;
  } else if (tiles_reflective == 0.0) {
    unknown = pixels;
  }

  ReflectionPathCosts result;
  const double reflective = tiles_reflective > 0.0 && pixels == 0.0 ? tiles_reflective : pixels;
  result.per_tile_ms = costs.classify_ms + costs.ssr_fixed_ms + costs.ray_fixed_ms + ssr * ssr_pixels + ray * rays +
                       std::min(ssr, ray) * unknown;
  result.all_rays_ms = costs.ray_fixed_ms + ray * reflective;
  if (inputs.ssr_suffices) result.all_ssr_ms = costs.ssr_fixed_ms + ssr * reflective;

  result.cheapest = ReflectionPath::per_tile;
  double best = result.per_tile_ms;
  if (result.all_rays_ms <= best) {
    result.cheapest = ReflectionPath::all_rays;
    best = result.all_rays_ms;
  }
  if (result.all_ssr_ms && *result.all_ssr_ms <= best) result.cheapest = ReflectionPath::all_ssr;
  return result;
}

}  // namespace glint::render
