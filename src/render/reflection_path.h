#pragma once
// The whole-frame choice of `--reflections auto` (docs/hybrid.md "auto"), as a pure function: per-tile
// decisions, or one method for the whole frame without any per-tile work.
//   per_tile  the tile classification, SSR (depth pyramid + march over the SSR tiles) and the ray
//             list over the ray tiles: pays the classification and both stages' fixed parts;
//   all_rays  no classification, no depth pyramid, no SSR: every reflective pixel is traced, as rt;
//   all_ssr   no classification, no rays: SSR over the whole image, as ssr; only while SSR alone
//             reflects the frame within the quality target.
// With R reflective pixels, marginal costs c_ssr and c_ray, fixed parts S (SSR), T (rays), K
// (classification):
//   all_rays = T + R c_ray        all_ssr = S + R c_ssr
//   per_tile = K + S + T + c_ssr (pixels of SSR tiles) + c_ray (rays the tiles want)
//              + min(c_ssr, c_ray) (pixels of tiles without history: their best case, since per-tile
//                                   decisions would learn them)
// The cheapest wins; on a tie a whole-frame path (it runs fewer passes than the model counts). When a
// ray costs no more than an SSR pixel, per_tile >= K + S + all_rays: all_rays, whatever SSR's
// failure rates.
#include "core/enum_names.h"
#include "render/reflection_cost_model.h"
#include "render/tile_classification.h"

#include <cstdint>
#include <optional>
#include <span>

namespace glint::render {

enum class ReflectionPath : std::uint32_t { per_tile = 0, all_rays = 1, all_ssr = 2 };
inline constexpr EnumNames<ReflectionPath, 3> kReflectionPathNames{
    "reflection path",
    {{ReflectionPath::per_tile, "per_tile"}, {ReflectionPath::all_rays, "all_rays"}, {ReflectionPath::all_ssr, "all_ssr"}}};

struct ReflectionPathInputs {
  ReflectionStageCosts costs;
  TileThresholds thresholds;            // the tile rule's, as per-tile frames would use them
  std::span<const TileEvidence> tiles;  // the newest tiles read back (empty: none yet)
  double reflective_pixels = 0.0;       // the newest frame's (the tiles are scaled to it)
  bool ssr_suffices = false;            // SSR alone reflects the frame within the quality target
};

struct ReflectionPathCosts {
  double per_tile_ms = 0.0;
  double all_rays_ms = 0.0;
  std::optional<double> all_ssr_ms;  // nullopt: SSR alone does not suffice
  ReflectionPath cheapest = ReflectionPath::per_tile;
};

ReflectionPathCosts compare_reflection_paths(const ReflectionPathInputs& inputs);

}  // namespace glint::render
