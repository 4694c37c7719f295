// `glint render --primary compute|auto` as a user runs it: the compute rasteriser's frame is nearly the
// id draw's, run.json names it, without the visibility G-buffer it is a one-line error, and the
// default (auto) records which method it chose and why.
#include "app/cli_runner.h"
#include "core/image.h"
#include "metrics/rmse_psnr.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderPrimaryComputeCli = GlTest;

TEST_F(RenderPrimaryComputeCli, FrameIsNearlyTheIdDrawsAndRunRecordNamesIt) {
  TempFolder folder;
  const auto render = [&](const std::string& primary) {
    const fs::path out = folder.path() / primary;
    const CliResult r = run_glint("render atrium-simple --width 64 --height 36 --frames 2100 --gbuffer visibility "
                                  "--primary " + primary + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  };
  const fs::path computed = render("compute"), drawn = render("raster");
  const nlohmann::json run = nlohmann::json::parse(read_text_file(computed / "run.json"));
  EXPECT_EQ(run["options"]["primary"], "compute");
  EXPECT_EQ(run["options"]["gbuffer"], "visibility");
  EXPECT_EQ(run["primary_visibility"], nlohmann::json({{"method", "compute"}}));
  // Edge pixels only differ (tests/render/compute_visibility_test.cpp): 97.5 dB measured at 320x180.
  const double psnr =
      metrics::rmse_psnr(read_png(computed / "frame_02100.png"), read_png(drawn / "frame_02100.png")).psnr;
  EXPECT_GE(psnr, 45.0);
}

TEST_F(RenderPrimaryComputeCli, NeedsTheVisibilityGBuffer) {
  TempFolder folder;
  const fs::path out = folder.path() / "bad";
  const CliResult r = run_glint("render atrium-simple --width 64 --height 36 --frames 2100 --gbuffer raster "
                                "--primary compute --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--gbuffer visibility"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "frame_02100.png"));
}

TEST_F(RenderPrimaryComputeCli, AutoIsTheDefaultAndRunRecordSaysWhatItChose) {
  TempFolder folder;
  const auto run_record = [&](const std::string& name, const std::string& flags) {
    const fs::path out = folder.path() / name;
    const CliResult r = run_glint("render atrium-simple --width 64 --height 36 --frames 2100 " + flags + " --out " +
                                  quoted(out));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return nlohmann::json::parse(read_text_file(out / "run.json"));
  };
  const nlohmann::json chosen = run_record("default", "");
  EXPECT_EQ(chosen["options"]["primary"], "auto");
  const nlohmann::json& primary = chosen["primary_visibility"];
  ASSERT_TRUE(primary.is_object()) << chosen.dump();
  const std::string method = primary["method"].get<std::string>();
  EXPECT_TRUE(method == "raster" || method == "compute") << method;
  EXPECT_NE(primary["chosen_by"].get<std::string>().find("--primary auto"), std::string::npos);
  if (primary.contains("raster_ms")) {  // a GPU timed both; a software renderer keeps the id draw untimed
    const double raster_ms = primary["raster_ms"], compute_ms = primary["compute_ms"];
    EXPECT_GT(raster_ms, 0.0);
    EXPECT_EQ(method, compute_ms * 1.25 < raster_ms ? "compute" : "raster");
  } else {
    EXPECT_EQ(method, "raster");
  }
  // The raster G-buffer makes no ids, so there is nothing to choose.
  EXPECT_TRUE(run_record("raster-gbuffer", "--gbuffer raster")["primary_visibility"].is_null());
}

}  // namespace
}  // namespace glint::testing
