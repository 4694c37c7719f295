// `glint render --reflections auto` and `glint bench --experiment adaptive`'s pure parts: the budget
// flags reach the frame (rays traced never above --ray-budget, auto's timings.csv columns filled),
// flag errors, and the Pareto front the adaptive report marks.
#include "app/bench/adaptive_experiment.h"
#include "app/cli_runner.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderAutoCli = GlTest;

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto found = std::find(header.begin(), header.end(), name);
  EXPECT_NE(found, header.end()) << name;
  return static_cast<std::size_t>(found - header.begin());
}

TEST_F(RenderAutoCli, TheRayBudgetHoldsAndTheTilesAreRecorded) {
  TempFolder folder;
  const fs::path out = folder.path() / "auto";
  const CliResult r = run_glint("render atrium-simple --reflections auto --ray-budget 40 --timings-only --width 64 "
                                "--height 36 --frames 2100:2102 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto rows = read_csv(out / "timings.csv");
  ASSERT_EQ(rows.size(), 4u);
  const auto& header = rows[0];
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    EXPECT_LE(std::stoul(row[column(header, "rays_traced")]), 40u);
    const double budget = std::stod(row[column(header, "ray_budget")]);  // 40, less while the camera moves
    EXPECT_LE(budget, 40.0);
    EXPECT_GE(budget, 40.0 * 0.25 - 1.0);
    EXPECT_LE(std::stod(row[column(header, "rays_traced")]), budget);
    std::size_t tiles = 0;
    for (const char* name : {"tiles_none", "tiles_ssr_only", "tiles_ssr_fallback", "tiles_rt_only"})
      tiles += std::stoul(row[column(header, name)]);
    EXPECT_EQ(tiles, 8u * 5u) << "every 8x8 tile of 64x36 has one class";
    EXPECT_FALSE(row[column(header, "classify_ms")].empty());
  }
}

TEST_F(RenderAutoCli, BudgetFlagsAreCheckedAndExcludeEachOther) {
  TempFolder folder;
  const std::string out = quoted(folder.path() / "auto");
  EXPECT_EQ(run_glint("render atrium-simple --reflections auto --ray-budget 10 --reflection-budget 1 --out " + out)
                .exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --reflections auto --reflection-budget -1 --out " + out).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --reflections auto --auto-quality 2 --out " + out).exit_code, 2);
}

TEST(AdaptiveExperiment, ParetoFrontKeepsOnlyPointsNothingBeats) {
  // cost, quality: (1, 0.9) (2, 0.95) (3, 0.93) (2, 0.95) (0.5, 0.5): the third is beaten by the second.
  const std::vector<bool> front =
      bench::pareto_front({1.0, 2.0, 3.0, 2.0, 0.5}, {0.9, 0.95, 0.93, 0.95, 0.5});
  EXPECT_EQ(front, (std::vector<bool>{true, true, false, true, true}));
}

TEST(AdaptiveExperiment, ConfigurationsCoverEveryModeAndTheBudgets) {
  const std::vector<bench::AdaptiveConfig> configs = bench::adaptive_configs(100, 50);
  ASSERT_EQ(configs.size(), 4u + std::size(bench::kAdaptiveBudgetFractions));
  EXPECT_EQ(configs[0].reflections, "rt") << "the reference renders first";
  EXPECT_EQ(configs.back().ray_budget, 750) << "15 % of 5000 pixels";
}

}  // namespace
}  // namespace glint::testing
