// `glint render`'s pipelined loop: timings.csv has every requested frame exactly once, in frame
// order, with every column filled that the mode measures, and a PNG for each of those frames.
#include "app/cli_runner.h"
#include "core/image.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

TEST(RenderTimingsRows, EveryFrameOnceInOrderWithNoEmptyField) {
  TempFolder folder;
  const fs::path out = folder.path() / "run";
  const CliResult r = run_glint("render atrium-simple --reflections hybrid --backend cpu --width 32 --height 18 "
                                "--frames 100:112:2,200 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> frames = {"100", "102", "104", "106", "108", "110", "112", "200"};
  const auto csv = read_csv(out / "timings.csv");
  ASSERT_EQ(csv.size(), frames.size() + 1) << "header + one row per frame";
  const std::vector<std::string>& header = csv[0];
  for (std::size_t row = 1; row < csv.size(); ++row) {
    ASSERT_EQ(csv[row].size(), header.size());
    EXPECT_EQ(csv[row][0], frames[row - 1]) << "frame order";
    for (std::size_t column = 0; column < header.size(); ++column) {
      if (header[column] == "gpu_memory_used_mb") continue;  // NVIDIA drivers only
      if (column > 19) continue;  // --reflections auto's columns (classify_ms ... rays_wanted)
      EXPECT_FALSE(csv[row][column].empty()) << "frame " << frames[row - 1] << ", " << header[column];
    }
    const ImageRgba8 image = read_png(out / ("frame_00" + frames[row - 1] + ".png"));
    EXPECT_EQ(image.width, 32);
  }
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary left behind: " << entry.path();
}

// accel_update_ms is the tracer's update: written whenever a tracer exists (here only the shadows
// trace rays, the deforming meshes' structures are refitted every frame), empty without one.
TEST(RenderTimingsRows, StructureUpdateIsRecordedWhenOnlyTheShadowsTraceRays) {
  TempFolder folder;
  const auto accel_update_column = [&](const char* shadows) {
    const fs::path out = folder.path() / shadows;
    const CliResult r = run_glint(std::string("render atrium-simple --reflections ssr --shadows ") + shadows +
                                  " --deform on --update refit --backend cpu --width 32 --height 18 --frames 100:101 "
                                  "--timings-only --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const auto csv = read_csv(out / "timings.csv");
    std::vector<std::string> column;
    for (std::size_t c = 0; !csv.empty() && c < csv[0].size(); ++c)
      if (csv[0][c] == "accel_update_ms")
        for (std::size_t row = 1; row < csv.size(); ++row) column.push_back(csv[row][c]);
    return column;
  };
  const std::vector<std::string> traced = accel_update_column("rt");
  ASSERT_EQ(traced.size(), 2u);
  for (const std::string& value : traced) EXPECT_FALSE(value.empty());
  const std::vector<std::string> cube = accel_update_column("cube");
  ASSERT_EQ(cube.size(), 2u);
  for (const std::string& value : cube) EXPECT_TRUE(value.empty()) << value;
}

}  // namespace
}  // namespace glint::testing
