// `glint render --profile-scopes` as a user runs it: scopes.csv has every frame's passes and the
// scopes nested in them, children within their parent; no scopes.csv without the flag; an earlier
// run's scopes.csv is an earlier run's file; an output that cannot be written is one line.
#include "app/cli_runner.h"
#include "cuda/device_query.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderScopesCli = GlTest;

constexpr const char* kSmallRun = "render atrium-simple --width 64 --height 36 --frames 0:3 --timings-only ";

struct Scope {
  std::string path;
  int depth = 0;
  double ms = 0.0;
};

// scopes.csv's rows by frame, in file order (the header checked).
std::map<int, std::vector<Scope>> read_scopes(const fs::path& file) {
  const std::vector<std::vector<std::string>> rows = read_csv(file);
  EXPECT_FALSE(rows.empty());
  if (rows.empty()) return {};
  EXPECT_EQ(rows[0], (std::vector<std::string>{"frame", "scope", "depth", "ms"}));
  std::map<int, std::vector<Scope>> frames;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].size(), 4u) << "row " << i;
    if (rows[i].size() != 4) continue;
    frames[std::stoi(rows[i][0])].push_back({rows[i][1], std::stoi(rows[i][2]), std::stod(rows[i][3])});
  }
  return frames;
}

std::string parent_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

TEST_F(RenderScopesCli, WritesEveryFramesNestedScopesWithinTheirParents) {
  TempFolder folder;
  const fs::path out = folder.path() / "run";
  const CliResult r = run_glint(std::string(kSmallRun) + "--primary compute --shadows rt --profile-scopes --out " +
                                quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["options"]["profile_scopes"], true);
  const bool wall_clock = run["gl"]["pass_timing"] == "finish_wall_clock";

  const std::map<int, std::vector<Scope>> frames = read_scopes(out / "scopes.csv");
  ASSERT_EQ(frames.size(), 4u);
  for (const auto& [frame, scopes] : frames) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    std::map<std::string, double> ms;
    std::map<std::string, double> children_ms;
    for (const Scope& scope : scopes) {
      EXPECT_GE(scope.ms, 0.0) << scope.path;
      EXPECT_EQ(scope.depth, static_cast<int>(std::count(scope.path.begin(), scope.path.end(), '/'))) << scope.path;
      const std::string parent = parent_of(scope.path);
      // Tree order: a parent's row comes before its children's.
      if (!parent.empty()) {
        EXPECT_TRUE(ms.contains(parent)) << scope.path;
      }
      ms[scope.path] += scope.ms;
      if (!parent.empty()) children_ms[parent] += scope.ms;
    }
    // The top-level passes of a hybrid frame (timings.csv's columns), and the scopes inside them.
    for (const char* path : {"gbuffer", "shadow", "light", "ssr", "ray_list", "hit_shade", "resolve",
                             "gbuffer/compute_visibility", "gbuffer/compute_visibility/triangles",
                             "gbuffer/compute_visibility/tiles", "gbuffer/compute_visibility/reset",
                             "gbuffer/visibility_gbuffer", "shadow/shadow_rays/ray_generation",
                             "shadow/shadow_rays/trace", "shadow/shadow_rays/mask"})
      EXPECT_TRUE(ms.contains(path)) << path;
    // glFinish intervals nest; so do GPU timestamps, each taken once everything before it completed.
    for (const auto& [parent, sum] : children_ms) {
      ASSERT_TRUE(ms.contains(parent)) << parent;
      // Six significant digits in the file: a little rounding slack.
      EXPECT_LE(sum, ms[parent] * (1.0 + 1e-5) + 1e-3) << parent;
    }
  }

  // A pass's scope encloses the timer's pass (finish_wall_clock: its glFinish calls are outside).
  if (wall_clock) {
    const std::vector<std::vector<std::string>> timings = read_csv(out / "timings.csv");
    const auto column = std::find(timings[0].begin(), timings[0].end(), "gbuffer_ms") - timings[0].begin();
    for (std::size_t row = 1; row < timings.size(); ++row) {
      const int frame = std::stoi(timings[row][0]);
      const double pass_ms = std::stod(timings[row][static_cast<std::size_t>(column)]);
      EXPECT_LE(pass_ms, frames.at(frame).front().ms * (1.0 + 1e-5) + 1e-3) << "frame " << frame;
    }
  }
}

TEST_F(RenderScopesCli, NoScopesCsvWithoutTheFlagAndAnEarlierOneIsAnEarlierRunsFile) {
  TempFolder folder;
  const fs::path out = folder.path() / "run";
  fs::create_directories(out);
  folder.write("run/scopes.csv", "frame,scope,depth,ms\n0,old,0,1\n");
  // A stale scopes.csv next to a new run's timings would mix two runs: refused like timings.csv.
  const CliResult refused = run_glint(std::string(kSmallRun) + "--out " + quoted(out));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_EQ(line_count(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("scopes.csv"), std::string::npos) << refused.err;

  const CliResult r = run_glint(std::string(kSmallRun) + "--overwrite --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "timings.csv"));
  EXPECT_FALSE(fs::exists(out / "scopes.csv")) << "removed with the earlier run, not written without the flag";
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["options"]["profile_scopes"], false);
}

TEST_F(RenderScopesCli, AnUnwritableScopesCsvIsOneLineAndWritesNothing) {
  TempFolder folder;
  const fs::path out = folder.path() / "run";
  // A folder in scopes.csv's place, with something in it: it cannot be replaced by the file.
  fs::create_directories(out / "scopes.csv");
  folder.write("run/scopes.csv/keep.txt", "x");
  const CliResult r = run_glint(std::string(kSmallRun) + "--profile-scopes --overwrite --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("scopes.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "timings.csv"));
  EXPECT_FALSE(fs::exists(out / "run.json"));

  const CliResult unwritable = run_glint(std::string(kSmallRun) + "--profile-scopes --out /proc/self/glint-run");
  EXPECT_EQ(unwritable.exit_code, 1);
  EXPECT_EQ(line_count(unwritable.err), 1) << unwritable.err;
}

// GPU machines only: a CUDA trace runs beside GL, between mapping and unmapping GL's buffers; GL's
// commands after the unmap wait for it, so the scope around it holds the trace's kernel time.
TEST_F(RenderScopesCli, CudaTracesAreInsideTheScopesAroundThem) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "needs a CUDA GPU";
  TempFolder folder;
  const fs::path out = folder.path() / "cuda";
  const CliResult r = run_glint("render atrium-simple --width 320 --height 180 --frames 0:11 --timings-only "
                                "--backend cuda --shadows rt --reflections rt --profile-scopes --out " +
                                quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["gl"]["pass_timing"], "gpu_queries");
  const std::map<int, std::vector<Scope>> frames = read_scopes(out / "scopes.csv");
  const std::vector<std::vector<std::string>> timings = read_csv(out / "timings.csv");
  const auto column = std::find(timings[0].begin(), timings[0].end(), "trace_ms") - timings[0].begin();
  double trace_scope_ms = 0.0, trace_kernel_ms = 0.0;
  for (std::size_t row = 2; row < timings.size(); ++row) {  // the first frame pays for warm-up
    const int frame = std::stoi(timings[row][0]);
    trace_kernel_ms += std::stod(timings[row][static_cast<std::size_t>(column)]);
    bool shadow_trace = false;
    // docs/render.md "One hand-over a frame": the shadow rays are traced inside the reflection
    // trace's hand-over, the device_trace pass.
    for (const Scope& scope : frames.at(frame)) {
      if (scope.path == "device_trace/trace") trace_scope_ms += scope.ms;  // its GPU pass around it
      if (scope.path == "device_trace/trace/shadow_rays/trace") shadow_trace = scope.ms > 0.0;
    }
    EXPECT_TRUE(shadow_trace) << "frame " << frame;
  }
  // Map and unmap only add to the kernel's time; some slack for the two clocks.
  EXPECT_GE(trace_scope_ms, 0.8 * trace_kernel_ms);
}

}  // namespace
}  // namespace glint::testing
