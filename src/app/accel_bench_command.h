#pragma once
// `glint accel-bench [scene]`: builds every acceleration structure (glint's BVH builders and Embree's
// qualities) over a scene's world triangles, checks they find the same hits, and times builds,
// closest-hit queries, and rebuild vs refit of the deforming meshes. See docs/accel-bench.md.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace glint {

struct AccelBenchOptions {
  std::string scene = "atrium";
  std::string builders = "all";       // "all" or comma-separated candidate names
  std::string backend = "cpu";        // what "all" means: cpu, cuda (cuda-*) or optix (optix-*)
  std::string rays = "reflection";
  std::string frames = "1800,2100,2300,4400";
  int width = 640;
  int height = 360;
  int threads = 0;                    // 0: all hardware threads
  std::string json;                   // empty: no JSON
  int deform_frames = 100;
  int build_runs = 3;
  unsigned seed = 1;
  bool strict_hits = false;           // any disagreeing hit fails the run (exit kHitDisagreementExitCode)
};

// The exit status of an accel-bench run under --strict-hits whose structures disagree (after the
// table and the JSON are written); 1 stays "could not run" (glint::Error), 2 a bad flag.
inline constexpr int kHitDisagreementExitCode = 3;

void add_accel_bench_command(CLI::App& app, AccelBenchOptions& options);
int run_accel_bench_command(const AccelBenchOptions& options);

// The parsed forms of --builders and --frames; glint::Error with a one-line reason for bad text.
// Embree's four qualities are always appended (they are the reference columns) unless named already.
// "all" is every structure of `backend`: "cpu" (glint's CPU structures), "cuda" (cuda-*) or "optix" (optix-*).
std::vector<std::string> parse_structure_list(const std::string& text, const std::string& backend = "cpu");
std::vector<int> parse_frame_list(const std::string& text);

namespace accel_bench {
struct BenchReport;
}
// The run's verdict on its hit checks: every line of hit_problems(report) goes to stderr, as a
// warning (and 0 is returned) or, when `strict_hits`, as an error (and kHitDisagreementExitCode).
int hit_check_exit_code(const accel_bench::BenchReport& report, bool strict_hits);

}  // namespace glint
