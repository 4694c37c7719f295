#pragma once
// `glint bench --experiment adaptive` (docs/bench.md "adaptive", docs/hybrid.md "auto"): quality
// against reflection cost for ssr, hybrid, rt and auto (unbudgeted and at a few ray budgets) on
// every scene given (--scene, --simple-scene), at the quality frames of Tables I/II (those the
// walkthrough has), each after --warmup frames of the walkthrough just before it so auto has its
// history, and rendered three times (the render with the least reflection time is kept: a shared
// machine's other work only adds time). Writes DIR/adaptive.csv (one row per scene, frame and configuration), DIR/summary.json
// (experiment "adaptive": per scene and configuration the means and whether the point is on the
// Pareto front), DIR/report.md (a table per scene) and the Pareto chart (charts/adaptive.png/svg)
// through tools/plot_bench.py. Not resumable: a run renders everything again.
#include "app/bench_command.h"

#include <string>
#include <vector>

namespace glint::bench {

// One configuration of the experiment: a reflection mode and, for auto, a ray budget.
struct AdaptiveConfig {
  std::string label;        // "ssr", "hybrid", "rt", "auto", "auto-2%" ...
  std::string reflections;  // glint render --reflections
  long long ray_budget = -1;  // --ray-budget; -1: none
};

// Ray budgets of auto, as fractions of the image's pixels.
inline constexpr double kAdaptiveBudgetFractions[] = {0.02, 0.05, 0.15};
std::vector<AdaptiveConfig> adaptive_configs(int width, int height);

// Which points are on the Pareto front of low cost and high quality: no other point is at most as
// dear and at least as good, and better in one of the two.
std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& quality);

int run_adaptive_experiment(const BenchOptions& options);

}  // namespace glint::bench
