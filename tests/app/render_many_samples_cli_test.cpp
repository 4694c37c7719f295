// Frames of many reflection samples on the GPU backends (--spp N): each sample traces two timed CUDA
// spans, so a 64-sample frame traces more than the 64 spans the backends' time ring once kept. The
// frame's structure update was timed before them; its time must still reach timings.csv and run.json
// rather than fail as a span read after its slot was reused (what the 256-sample reference did on the
// H200). The backends now keep every span until it is read (cuda/gpu_span_pool.h).
#include "app/cli_runner.h"
#include "cuda/device_query.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

class RenderManySamplesCli : public ::testing::TestWithParam<const char*> {};

TEST_P(RenderManySamplesCli, TheUpdateTimeOfAFrameOfManySamplesIsReported) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "needs a CUDA GPU";
  const std::string backend = GetParam();
  TempFolder folder;
  const fs::path out = folder.path() / backend;
  // atrium-simple deforms its dinosaurs: every frame refits the structure on the GPU.
  const CliResult r = run_glint("render atrium-simple --width 160 --height 90 --frames 2100:2101 --timings-only "
                                "--glossy on --reflections rt --spp 64 --update refit --backend " +
                                backend + " --out " + quoted(out));
  if (r.exit_code != 0 && r.err.find("built without") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::vector<std::string>> timings = read_csv(out / "timings.csv");
  ASSERT_EQ(timings.size(), 3u);
  const auto column = static_cast<std::size_t>(
      std::find(timings[0].begin(), timings[0].end(), "accel_update_ms") - timings[0].begin());
  ASSERT_LT(column, timings[0].size());
  for (std::size_t row = 1; row < timings.size(); ++row) EXPECT_GT(std::stod(timings[row][column]), 0.0) << row;
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  // Written from the tracer's final stats, which read the last update's time too.
  EXPECT_GE(run["ray_tracer"]["refits"].get<int>(), 2) << run["ray_tracer"].dump();
}

INSTANTIATE_TEST_SUITE_P(GpuBackends, RenderManySamplesCli, ::testing::Values("cuda", "optix"));

}  // namespace
}  // namespace glint::testing
