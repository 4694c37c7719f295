#pragma once
// The per-tile decision of `--reflections auto` (docs/hybrid.md "auto"), as pure functions: which
// reflection method each 8x8 tile of the frame gets, from what the tile's pixels said about SSR the
// frames before (reprojected on the GPU by TileClassifyPass) and what SSR and rays cost.
//
// For a tile of R reflective pixels whose SSR fails on a fraction f, with c_ssr ms per SSR pixel and
// c_ray ms per traced ray (list + trace + hit shading):
//   rt only       costs R c_ray                 every pixel reflected
//   SSR + rays    costs R c_ssr + f R c_ray      every pixel reflected (SSR's trusted hits, rays for the rest)
//   SSR only      costs R c_ssr                 f R pixels unreflected
// so rays alone win when f >= 1 - c_ssr / c_ray, and SSR alone is allowed where f is within the
// quality target (and SSR is cheaper than a ray). choose_tile_thresholds turns that into two
// thresholds on f; a ray budget then raises them (rt tiles become SSR + rays first, which loses
// nothing; then SSR + rays tiles become SSR only, lowest f first, as long as the rays left still fill
// the budget: the ray list's cap cuts the last few). classify_tile applies them to
// one tile; shaders/include/tile_class_rule.glsl is its GLSL twin (kept equal by
// tests/render/tile_classification_test.cpp).
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "core/enum_names.h"

namespace glint::render {

// Values as the GPU stores them (tile evidence .w, tile_class_rule.glsl).
enum class TileClass : std::uint32_t { none = 0, ssr_only = 1, ssr_fallback = 2, rt_only = 3 };
inline constexpr EnumNames<TileClass, 4> kTileClassNames{
    "tile class",
    {{TileClass::none, "none"}, {TileClass::ssr_only, "ssr_only"}, {TileClass::ssr_fallback, "ssr_fallback"},
     {TileClass::rt_only, "rt_only"}}};
inline constexpr std::uint32_t kTileClassCount = 4;

// What the GPU knew of a tile's reflective pixels when it classified it.
struct TileEvidence {
  std::uint32_t reflective = 0;    // reflective pixels of the tile this frame
  std::uint32_t known = 0;         // of those, pixels whose SSR outcome is known from earlier frames
  std::uint32_t failed_known = 0;  // of the known, pixels SSR failed on
};

// The thresholds on a tile's predicted SSR failure rate f = failed_known / known.
struct TileThresholds {
  float ssr_only_at_most = 0.0f;  // f <= this: SSR only (negative: never)
  float rt_at_least = 1.0f;       // otherwise f >= this: rays only; else SSR + rays
  // A tile with fewer known pixels than this fraction of its reflective ones gets SSR + rays: it is
  // new on screen (or its surface was), and SSR there both reflects it and learns its failure rate.
  // Where rays win at any failure rate (rt_at_least <= 0) it gets rays only instead.
  float min_known_fraction = 0.5f;
};

TileClass classify_tile(const TileEvidence& tile, const TileThresholds& thresholds);
// Whether enough of the tile's reflective pixels are known for its failure rate to count.
bool known_enough(const TileEvidence& tile, const TileThresholds& thresholds);
// failed_known / known (known > 0), in the steps the GLSL twin computes bit for bit.
float failure_rate(const TileEvidence& tile);

struct ReflectionCosts {
  double ms_per_ssr_pixel = 0.0;  // SSR pass time per reflective pixel it marched
  double ms_per_ray = 0.0;        // ray list + trace + hit shading per traced ray
};

struct ThresholdInputs {
  ReflectionCosts costs;
  // The quality target: the largest fraction of a tile's reflective pixels that may stay unreflected
  // (SSR only). 0: SSR only where SSR failed on no pixel.
  float max_unreflected_fraction = 0.0f;
  // Rays the frame may trace (nullopt: no budget).
  std::optional<double> ray_budget;
  // Failure rate assumed for tiles without enough history, for the expected ray count.
  float unknown_failure_rate = 0.5f;
};

// Thresholds for the next frame from the tiles of the last one the host has read (any order).
TileThresholds choose_tile_thresholds(std::span<const TileEvidence> tiles, const ThresholdInputs& inputs);

// Rays the tiles would ask for under `thresholds` (unknown tiles at `unknown_failure_rate`).
double expected_rays(std::span<const TileEvidence> tiles, const TileThresholds& thresholds,
                     float unknown_failure_rate);

// A budget in milliseconds as rays: what is left of `budget_ms` after SSR on the tiles that would
// march it under the cost-optimal thresholds, at costs.ms_per_ray each (>= 0).
double rays_within_ms(std::span<const TileEvidence> tiles, const ThresholdInputs& inputs, double budget_ms);

}  // namespace glint::render
