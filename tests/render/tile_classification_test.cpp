// --reflections auto's decisions on the host (render/tile_classification.h, reflection_cost_model.h,
// reflection_budget.h): the tile rule follows the cost model it is given, a ray budget is met by
// demoting tiles in the stated order, the GLSL twin of the rule agrees with the C++ one, the cost
// model calibrates and follows the timers, and camera motion lowers and restores the budget.
#include "gl/embedded_shaders.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/reflection_budget.h"
#include "render/reflection_cost_model.h"
#include "render/tile_classification.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace glint::render {
namespace {

// A tile of 64 reflective pixels, all known, `failed` of them failed.
TileEvidence tile(std::uint32_t failed, std::uint32_t reflective = 64) { return {reflective, reflective, failed}; }

ThresholdInputs with_costs(double ssr, double ray) {
  ThresholdInputs inputs;
  inputs.costs = {ssr, ray};
  return inputs;
}

TEST(TileClassification, FollowsTheCostModelItIsGiven) {
  // A ray costs 4 SSR pixels: rays alone pay from f = 1 - 1/4 = 0.75 on.
  const TileThresholds cheap_ssr = choose_tile_thresholds({}, with_costs(1.0, 4.0));
  EXPECT_FLOAT_EQ(cheap_ssr.rt_at_least, 0.75f);
  EXPECT_EQ(classify_tile(tile(0), cheap_ssr), TileClass::ssr_only);      // nothing fails: SSR alone
  EXPECT_EQ(classify_tile(tile(1), cheap_ssr), TileClass::ssr_fallback);  // quality target 0: rays for the failure
  EXPECT_EQ(classify_tile(tile(47), cheap_ssr), TileClass::ssr_fallback);  // f = 0.73
  EXPECT_EQ(classify_tile(tile(48), cheap_ssr), TileClass::rt_only);      // f = 0.75
  EXPECT_EQ(classify_tile(tile(64), cheap_ssr), TileClass::rt_only);

  // Rays ten times dearer: SSR + rays up to f = 0.9.
  const TileThresholds dear_rays = choose_tile_thresholds({}, with_costs(1.0, 10.0));
  EXPECT_EQ(classify_tile(tile(48), dear_rays), TileClass::ssr_fallback);
  EXPECT_EQ(classify_tile(tile(58), dear_rays), TileClass::rt_only);

  // A ray cheaper than an SSR pixel (the H100 atrium of issue 21): rays everywhere, even where SSR never fails.
  const TileThresholds cheap_rays = choose_tile_thresholds({}, with_costs(2.0, 1.0));
  EXPECT_EQ(classify_tile(tile(0), cheap_rays), TileClass::rt_only);
  EXPECT_EQ(classify_tile(tile(20), cheap_rays), TileClass::rt_only);

  // The quality target lets SSR leave up to 10 % of a tile unreflected.
  ThresholdInputs lenient = with_costs(1.0, 4.0);
  lenient.max_unreflected_fraction = 0.1f;
  const TileThresholds relaxed = choose_tile_thresholds({}, lenient);
  EXPECT_EQ(classify_tile(tile(6), relaxed), TileClass::ssr_only);
  EXPECT_EQ(classify_tile(tile(7), relaxed), TileClass::ssr_fallback);
}

TEST(TileClassification, TilesWithoutHistoryRunSsrWithRaysAndEmptyTilesNothing) {
  const TileThresholds thresholds = choose_tile_thresholds({}, with_costs(1.0, 4.0));
  EXPECT_EQ(classify_tile({0, 0, 0}, thresholds), TileClass::none);
  EXPECT_EQ(classify_tile({64, 0, 0}, thresholds), TileClass::ssr_fallback);
  EXPECT_EQ(classify_tile({64, 31, 31}, thresholds), TileClass::ssr_fallback) << "under half known";
  EXPECT_EQ(classify_tile({64, 32, 32}, thresholds), TileClass::rt_only);
}

TEST(TileClassification, ABudgetDemotesRaysOnlyTilesFirstThenSsrWithRaysTiles) {
  // Tiles f = 1, 0.9, 0.5, 0.25: cost-optimal at c_ssr/c_ray = 0.2 makes the first two rays only.
  const std::vector<TileEvidence> tiles{tile(64), tile(58), tile(32), tile(16)};
  ThresholdInputs inputs = with_costs(1.0, 5.0);
  const TileThresholds free = choose_tile_thresholds(tiles, inputs);
  EXPECT_DOUBLE_EQ(expected_rays(tiles, free, 0.5f), 64 + 64 + 32 + 16);

  // 170 rays: the f = 0.9 tile goes to SSR + rays (saves 6 rays; nothing is lost).
  inputs.ray_budget = 170.0;
  const TileThresholds step1 = choose_tile_thresholds(tiles, inputs);
  EXPECT_EQ(classify_tile(tiles[0], step1), TileClass::rt_only);
  EXPECT_EQ(classify_tile(tiles[1], step1), TileClass::ssr_fallback);
  EXPECT_LE(expected_rays(tiles, step1, 0.5f), 170.0);

  // 100 rays: every tile runs SSR; the lowest failure rates lose their rays first, and the f = 0.9
  // tile keeps its 58 rays: without them only 64 of the 100 would be spent (the ray list's cap cuts
  // the 22 over).
  inputs.ray_budget = 100.0;
  const TileThresholds step2 = choose_tile_thresholds(tiles, inputs);
  EXPECT_EQ(classify_tile(tiles[3], step2), TileClass::ssr_only);
  EXPECT_EQ(classify_tile(tiles[2], step2), TileClass::ssr_only);
  EXPECT_EQ(classify_tile(tiles[1], step2), TileClass::ssr_fallback);
  EXPECT_EQ(classify_tile(tiles[0], step2), TileClass::ssr_fallback);
  EXPECT_DOUBLE_EQ(expected_rays(tiles, step2, 0.5f), 122.0);
}

TEST(TileClassification, ABudgetIsSpentAndOnlyTheLastGroupIsLeftToTheCap) {
  std::mt19937 random(21);
  std::uniform_int_distribution<std::uint32_t> failed(0, 64);
  for (int round = 0; round < 50; ++round) {
    std::vector<TileEvidence> tiles;
    for (int i = 0; i < 200; ++i) tiles.push_back(tile(failed(random)));
    ThresholdInputs inputs = with_costs(1.0, 1.0 + round % 7);
    inputs.ray_budget = 40.0 * round;
    const TileThresholds thresholds = choose_tile_thresholds(tiles, inputs);
    const TileThresholds unlimited = choose_tile_thresholds(tiles, with_costs(1.0, 1.0 + round % 7));
    const double wanted = expected_rays(tiles, unlimited, 0.5f);
    const double kept = expected_rays(tiles, thresholds, 0.5f);
    if (wanted <= *inputs.ray_budget) {
      EXPECT_DOUBLE_EQ(kept, wanted) << "round " << round << ": within the budget nothing changes";
      continue;
    }
    if (kept < *inputs.ray_budget) {
      // Under the budget only by moving rays-only tiles to SSR + rays, which loses no pixel.
      EXPECT_EQ(thresholds.ssr_only_at_most, unlimited.ssr_only_at_most) << "round " << round;
      continue;
    }
    // What is over the budget is at most one group of equal failure rate (64 pixels per tile here).
    EXPECT_LE(kept - *inputs.ray_budget, 200.0 * 64.0) << "round " << round;
    // Lowering the SSR-only threshold to the next rate below would leave the budget unspent:
    // no group that could still have moved was kept.
    TileThresholds one_more = thresholds;
    float next = 2.0f;
    for (const TileEvidence& t : tiles) {
      const float f = static_cast<float>(t.failed_known) / static_cast<float>(t.known);
      if (f > thresholds.ssr_only_at_most && f < thresholds.rt_at_least) next = std::min(next, f);
    }
    if (next <= 1.0f) {
      one_more.ssr_only_at_most = next;
      EXPECT_LT(expected_rays(tiles, one_more, 0.5f), *inputs.ray_budget) << "round " << round;
    }
  }
}

TEST(TileClassification, AMillisecondBudgetLeavesRaysAfterSsr) {
  const std::vector<TileEvidence> tiles{tile(0), tile(10)};  // both run SSR: 128 SSR pixels
  EXPECT_DOUBLE_EQ(rays_within_ms(tiles, with_costs(0.001, 0.01), 1.0), (1.0 - 0.128) / 0.01);
  EXPECT_DOUBLE_EQ(rays_within_ms(tiles, with_costs(0.01, 0.02), 1.0), 0.0) << "SSR alone takes 1.28 ms";
}

TEST(ReflectionCostModelTest, TheFirstSampleReplacesThePriorAndSimilarOnesAreAveraged) {
  ReflectionCostModel model(ReflectionCosts{1.0, 1.0});
  model.observe({2.0, 1000, 0.0, 0});  // SSR only: 0.002 ms per pixel
  EXPECT_DOUBLE_EQ(model.costs().ms_per_ssr_pixel, 0.002);
  EXPECT_DOUBLE_EQ(model.costs().ms_per_ray, 1.0) << "no ray measured yet: the prior";
  model.observe({0.0, 0, 5.0, 1000});
  EXPECT_DOUBLE_EQ(model.costs().ms_per_ray, 0.005);
  model.observe({2.02, 1010, 5.0, 1000});  // too close to the first to fit a line: the average
  EXPECT_DOUBLE_EQ(model.costs().ms_per_ssr_pixel, 0.002);
}

TEST(ReflectionCostModelTest, TheCostIsTheMarginalOneOnceTheWorkVaries) {
  // Rays cost 1 ms fixed (dispatch, fence) + 0.001 ms each: 2 ms for 1000 rays (0.002 ms a ray on
  // average), 11 ms for 10000 (0.0011). A tile's choice moves only the 0.001.
  ReflectionCostModel model(ReflectionCosts{1.0, 1.0});
  model.observe({0.0, 0, 2.0, 1000});
  EXPECT_DOUBLE_EQ(model.costs().ms_per_ray, 0.002);
  model.observe({0.0, 0, 11.0, 10000});
  EXPECT_NEAR(model.costs().ms_per_ray, 0.001, 1e-12);
  model.observe({0.0, 0, 6.0, 5000});
  EXPECT_NEAR(model.costs().ms_per_ray, 0.001, 1e-12);

  const ReflectionCostModel fixed(ReflectionCosts{1.0, 1.0}, ReflectionStageCosts{{3.0, 4.0}, 0.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(fixed.costs().ms_per_ray, 4.0);
}

TEST(ReflectionBudgetTest, FastMotionLowersTheBudgetAndAStillCameraRestoresIt) {
  ReflectionBudget budget;
  budget.rays = 1000;
  CameraState still;
  still.position = vec3(0.0f);
  still.target = vec3(0.0f, 0.0f, -1.0f);
  CameraState turned = still;
  turned.target = vec3(std::sin(0.2f), 0.0f, -std::cos(0.2f));  // 0.2 rad of a 60 degree field: a fifth of the screen
  EXPECT_FLOAT_EQ(camera_motion(still, still, 10.0f), 0.0f);
  EXPECT_GT(camera_motion(still, turned, 10.0f), budget.fast_motion);

  BudgetGovernor governor(budget);
  EXPECT_FLOAT_EQ(governor.next(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(governor.next(camera_motion(still, turned, 10.0f)), budget.fast_motion_factor);
  float previous = governor.factor();
  int frames = 0;
  while (governor.factor() < 1.0f && frames < 100) {
    EXPECT_GT(governor.next(0.0f), previous) << "each still frame gives some budget back";
    previous = governor.factor();
    ++frames;
  }
  EXPECT_FLOAT_EQ(governor.factor(), 1.0f);
  EXPECT_GT(frames, 1) << "restored over frames, not at once";
}

// The GLSL twin (shaders/include/tile_class_rule.glsl) decides every tile as classify_tile does.
using TileRuleTwinTest = testing::GlTest;

TEST_F(TileRuleTwinTest, TheShaderRuleEqualsTheHostRule) {
  const std::string source = std::string("#version 450 core\nlayout(local_size_x = 64) in;\n") +
                             std::string(shader_source("include/tile_class_rule.glsl")) + R"(
layout(std430, binding = 0) readonly buffer Tiles { uvec4 tiles[]; };
layout(std430, binding = 1) writeonly buffer Classes { uint classes[]; };
uniform float ssr_only_at_most, rt_at_least, min_known_fraction;
uniform int count;
void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= uint(count)) return;
  classes[i] = classify_tile(tiles[i].x, tiles[i].y, tiles[i].z, ssr_only_at_most, rt_at_least, min_known_fraction);
})";
  ShaderProgram program = ShaderProgram::from_sources({{GL_COMPUTE_SHADER, "tile_rule_twin.comp.glsl", source}});
  std::vector<std::uint32_t> words;
  std::vector<TileEvidence> tiles;
  for (std::uint32_t reflective : {0u, 1u, 7u, 64u})
    for (std::uint32_t known = 0; known <= reflective; ++known)
      for (std::uint32_t failed = 0; failed <= known; ++failed) {
        tiles.push_back({reflective, known, failed});
        words.insert(words.end(), {reflective, known, failed, 0u});
      }
  for (const TileThresholds thresholds : {TileThresholds{0.0f, 0.75f, 0.5f}, TileThresholds{-1.0f, 0.0f, 0.5f},
                                          TileThresholds{0.1f, 1.0f, 0.25f}, TileThresholds{0.5f, 0.3f, 1.0f}}) {
    const GlBuffer input = create_buffer(std::span<const std::uint32_t>(words));
    const GlBuffer output = create_buffer(tiles.size() * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
    program.set_uniform("ssr_only_at_most", thresholds.ssr_only_at_most);
    program.set_uniform("rt_at_least", thresholds.rt_at_least);
    program.set_uniform("min_known_fraction", thresholds.min_known_fraction);
    program.set_uniform("count", static_cast<int>(tiles.size()));
    program.use();
    glDispatchCompute(static_cast<GLuint>((tiles.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<std::uint32_t> classes(tiles.size());
    glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(classes.size() * sizeof(std::uint32_t)),
                            classes.data());
    for (std::size_t i = 0; i < tiles.size(); ++i)
      ASSERT_EQ(classes[i], static_cast<std::uint32_t>(classify_tile(tiles[i], thresholds)))
          << "tile " << tiles[i].reflective << "/" << tiles[i].known << "/" << tiles[i].failed_known;
  }
}

}  // namespace
}  // namespace glint::render
