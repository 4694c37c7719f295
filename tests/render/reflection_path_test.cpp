// --reflections auto's whole-frame choice and the cost lines it weighs (render/reflection_path.h,
// reflection_cost_model.h): rays cheaper per pixel than SSR mean all rays whatever SSR's failure
// rates; SSR cheaper keeps per-tile decisions where SSR fails on part of the frame; SSR that never
// fails is all SSR; the fixed parts (depth pyramid, classification, the ray stage's dispatches) decide
// between them; the cost lines keep their slope once the frames all do the same work.
#include "render/reflection_cost_model.h"
#include "render/reflection_path.h"

#include <gtest/gtest.h>

#include <vector>

namespace glint::render {
namespace {

TileEvidence tile(std::uint32_t failed, std::uint32_t reflective = 64) { return {reflective, reflective, failed}; }

ReflectionPathInputs inputs_for(const ReflectionStageCosts& costs, const std::vector<TileEvidence>& tiles,
                                double reflective) {
  ReflectionPathInputs inputs;
  inputs.costs = costs;
  ThresholdInputs optimal;
  optimal.costs = costs.marginal;
  inputs.thresholds = choose_tile_thresholds({}, optimal);
  inputs.tiles = tiles;
  inputs.reflective_pixels = reflective;
  return inputs;
}

TEST(ReflectionPath, RaysCheaperThanAnSsrPixelMeanAllRaysWhateverSsrDoes) {
  // The H200's atrium (docs/perf.md, fourth round): SSR 0.205 ms for 406k pixels of which the pyramid
  // and dispatch are ~0.065, the ray stage ~0.3 ms whatever the count (its slope ~0), the classification 0.045.
  const ReflectionStageCosts h200{{3.4e-7, 0.0}, 0.065, 0.30, 0.045};
  const std::vector<TileEvidence> none_fail(100, tile(0)), half_fail{tile(0), tile(32), tile(64), tile(10)};
  for (const std::vector<TileEvidence>* tiles : {&none_fail, &half_fail}) {
    ReflectionPathInputs inputs = inputs_for(h200, *tiles, 406000.0);
    const ReflectionPathCosts costs = compare_reflection_paths(inputs);
    EXPECT_EQ(costs.cheapest, ReflectionPath::all_rays);
    EXPECT_DOUBLE_EQ(costs.all_rays_ms, 0.30);
    EXPECT_GE(costs.per_tile_ms, 0.30 + 0.065 + 0.045);
  }
  // Without any tiles yet (every pixel unknown, counted at its best case) it is all rays too.
  EXPECT_EQ(compare_reflection_paths(inputs_for(h200, {}, 406000.0)).cheapest, ReflectionPath::all_rays);
  // Where SSR alone would do (it never fails), ssr's 0.20 ms beats rt's 0.30: all SSR.
  ReflectionPathInputs ssr_would_do = inputs_for(h200, none_fail, 406000.0);
  ssr_would_do.ssr_suffices = true;
  EXPECT_EQ(compare_reflection_paths(ssr_would_do).cheapest, ReflectionPath::all_ssr);
}

TEST(ReflectionPath, SsrCheaperKeepsPerTileDecisionsWhereSsrFailsOnPartOfTheFrame) {
  // A ray costs 10 SSR pixels; half the tiles never fail, half always do.
  const ReflectionStageCosts costs{{1e-6, 1e-5}, 0.01, 0.01, 0.01};
  std::vector<TileEvidence> tiles(500, tile(0));
  tiles.insert(tiles.end(), 500, tile(64));
  const ReflectionPathCosts result = compare_reflection_paths(inputs_for(costs, tiles, 64000.0));
  EXPECT_EQ(result.cheapest, ReflectionPath::per_tile);
  // 0.03 fixed + 32000 SSR pixels + 32000 rays.
  EXPECT_NEAR(result.per_tile_ms, 0.03 + 32000 * 1e-6 + 32000 * 1e-5, 1e-12);
  EXPECT_NEAR(result.all_rays_ms, 0.01 + 64000 * 1e-5, 1e-12);
  EXPECT_FALSE(result.all_ssr_ms);

  // Where SSR fails everywhere, per-tile decisions would make every tile rays only: the classification
  // and the pyramid would be paid for nothing.
  const std::vector<TileEvidence> failing(1000, tile(64));
  EXPECT_EQ(compare_reflection_paths(inputs_for(costs, failing, 64000.0)).cheapest, ReflectionPath::all_rays);
}

TEST(ReflectionPath, SsrThatSufficesIsAllSsrAndTheFixedPartsDecide) {
  const ReflectionStageCosts costs{{1e-6, 1e-5}, 0.01, 0.01, 0.01};
  const std::vector<TileEvidence> tiles(1000, tile(0));
  ReflectionPathInputs inputs = inputs_for(costs, tiles, 64000.0);
  EXPECT_EQ(compare_reflection_paths(inputs).cheapest, ReflectionPath::per_tile) << "not allowed: per-tile";
  inputs.ssr_suffices = true;
  const ReflectionPathCosts result = compare_reflection_paths(inputs);
  EXPECT_EQ(result.cheapest, ReflectionPath::all_ssr);
  EXPECT_NEAR(*result.all_ssr_ms, 0.01 + 0.064, 1e-12);

  // A depth pyramid dearer than the whole ray stage tips the same frame to rays.
  ReflectionStageCosts dear_pyramid = costs;
  dear_pyramid.ssr_fixed_ms = 1.0;
  inputs.costs = dear_pyramid;
  EXPECT_EQ(compare_reflection_paths(inputs).cheapest, ReflectionPath::all_rays);
}

TEST(ReflectionPath, OldTilesAreScaledToTodaysPixelCount) {
  const ReflectionStageCosts costs{{1e-6, 1e-5}, 0.0, 0.0, 0.0};
  std::vector<TileEvidence> tiles{tile(0), tile(64)};  // 128 pixels, half SSR only, half rays
  const ReflectionPathCosts result = compare_reflection_paths(inputs_for(costs, tiles, 1280.0));
  EXPECT_NEAR(result.per_tile_ms, 640 * 1e-6 + 640 * 1e-5, 1e-12);
  EXPECT_NEAR(result.all_rays_ms, 1280 * 1e-5, 1e-12);
}

TEST(ReflectionCostModelLines, TheSlopeAndFixedPartsSurviveASteadyState) {
  // The start-up calibration: SSR over 400k pixels (0.2 ms) and over none (0.06 ms: pyramid and
  // dispatch); rays 130k (0.33 ms) and 400k (0.34 ms). Then 60 frames of the same work: the points no
  // longer spread, and the lines must not fall back to time over items (which folds the fixed part
  // into the marginal cost and made a ray look twice as dear as an SSR pixel on the H200).
  ReflectionCostModel model(ReflectionCosts{1.0, 1.0});
  EXPECT_FALSE(model.measured());
  model.observe({0.20, 400000, 0.33, 130000, 0.045});
  model.observe({0.06, 0, 0.34, 400000, 0.045});
  EXPECT_TRUE(model.measured());
  for (int frame = 0; frame < 60; ++frame) model.observe({0.0, 0, 0.34, 400000, 0.0});  // all rays: no SSR, no classification
  const ReflectionStageCosts costs = model.stage_costs();
  EXPECT_NEAR(costs.marginal.ms_per_ssr_pixel, 0.14 / 400000, 1e-12);
  EXPECT_NEAR(costs.ssr_fixed_ms, 0.06, 1e-9);
  EXPECT_NEAR(costs.marginal.ms_per_ray, 0.01 / 270000, 1e-12);
  EXPECT_NEAR(costs.ray_fixed_ms, 0.34 - 400000 * (0.01 / 270000), 1e-6) << "through the steady frames";
  EXPECT_NEAR(costs.classify_ms, 0.045, 1e-12);
  EXPECT_EQ(compare_reflection_paths(inputs_for(costs, {}, 400000.0)).cheapest, ReflectionPath::all_rays);
}

TEST(ReflectionCostModelLines, ARayThatCostsNothingMoreIsTheCheapestNotAMissingMeasurement) {
  // The GPU's trace time does not grow with the rays: the fitted slope is 0.
  ThresholdInputs inputs;
  inputs.costs = {1e-6, 0.0};
  const TileThresholds thresholds = choose_tile_thresholds({}, inputs);
  EXPECT_FLOAT_EQ(thresholds.rt_at_least, 0.0f);
  EXPECT_EQ(classify_tile(tile(0), thresholds), TileClass::rt_only);
  EXPECT_EQ(classify_tile({64, 0, 0}, thresholds), TileClass::rt_only) << "no history: rays win at any failure rate";
}

}  // namespace
}  // namespace glint::render
