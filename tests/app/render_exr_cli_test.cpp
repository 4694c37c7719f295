// `glint render --format exr`: frames and debug views as linear float EXRs, the frame's colour taken
// before the tone map, so the renderer's own tone map (render/tone_map.h) turns the EXR into the PNG
// of the same frame; flags that cannot go with it are one line.
#include "app/cli_runner.h"
#include "core/exr_image.h"
#include "core/image.h"
#include "render/tone_map.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

// GlTest skips every test when this machine has no headless OpenGL 4.5 (the command would fail).
using RenderExrCli = GlTest;

const std::string kFrame =
    "render atrium-simple --backend cpu --reflections hybrid --width 48 --height 32 --frames 2100 --out ";

TEST_F(RenderExrCli, TheExrToneMappedByTheRenderersFunctionIsThePngOfTheSameFrame) {
  const TempFolder folder;
  const fs::path png_run = folder.path() / "png", exr_run = folder.path() / "exr";
  const CliResult png = run_glint(kFrame + quoted(png_run) + " --tone-map reinhard");
  ASSERT_EQ(png.exit_code, 0) << png.err;
  const CliResult exr = run_glint(kFrame + quoted(exr_run) + " --tone-map reinhard --format exr");
  ASSERT_EQ(exr.exit_code, 0) << exr.err;
  EXPECT_FALSE(fs::exists(exr_run / "frame_02100.png"));

  const ExrFile linear = read_exr(exr_run / "frame_02100.exr");
  EXPECT_EQ(linear.text.at(std::string(render::kExrToneMapAttribute)), "reinhard");
  const ImageRgba8 expected = read_png(png_run / "frame_02100.png");
  const ImageRgba8 mapped = render::tone_map_to_rgba8(linear.image, render::ToneMap::reinhard);
  ASSERT_EQ(mapped.width, 48);
  ASSERT_EQ(mapped.height, 32);
  int largest = 0;
  for (std::size_t i = 0; i < mapped.pixels.size(); ++i)
    for (glm::length_t c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(int(mapped.pixels[i][c]) - int(expected.pixels[i][c])));
  EXPECT_LE(largest, 1) << "the EXR tone mapped differs from the PNG by more than one 8-bit level";

  const nlohmann::json run = nlohmann::json::parse(read_text_file(exr_run / "run.json"));
  EXPECT_EQ(run["options"]["format"], "exr");
}

TEST_F(RenderExrCli, DebugViewsHoldTheirValuesNotTheirPictures) {
  const TempFolder folder;
  const fs::path exr_run = folder.path() / "exr";
  const CliResult exr = run_glint(kFrame + quoted(exr_run) + " --format exr --debug-views");
  ASSERT_EQ(exr.exit_code, 0) << exr.err;
  // Debug views: the values themselves (world units), not their 0..1 pictures.
  for (const char* view : {"albedo", "normals", "positions", "depth", "shadow_mask", "ssr_reflection", "failure_mask",
                           "traced_reflection", "reflection"})
    EXPECT_TRUE(fs::exists(exr_run / (std::string("frame_02100_") + view + ".exr"))) << view;
  const ExrFile depth = read_exr(exr_run / "frame_02100_depth.exr");
  float deepest = 0.0f;
  for (const glm::vec4& p : depth.image.pixels) deepest = std::max(deepest, p.x);
  EXPECT_GT(deepest, 1.0f) << "view depth in metres";
  const ExrFile normals = read_exr(exr_run / "frame_02100_normals.exr");
  const glm::vec3 centre(normals.image.at(24, 16));
  EXPECT_NEAR(glm::length(centre), 1.0f, 1e-3f) << "unit world normals, not 0.5 n + 0.5";
  EXPECT_FALSE(fs::exists(exr_run / "frame_02100_normals.png"));
}

TEST_F(RenderExrCli, VideoWithExrAndAnUnwritableOutputAreOneLineErrors) {
  const TempFolder folder;
  const CliResult video = run_glint(kFrame + quoted(folder.path() / "v") + " --format exr --video");
  EXPECT_EQ(video.exit_code, 1);
  EXPECT_EQ(line_count(video.err), 1) << video.err;
  EXPECT_NE(video.err.find("--video needs --format png"), std::string::npos) << video.err;
  EXPECT_FALSE(fs::exists(folder.path() / "v"));

  const CliResult unwritable = run_glint(kFrame + "/proc/self/glint-out --format exr");
  EXPECT_EQ(unwritable.exit_code, 1);
  EXPECT_EQ(line_count(unwritable.err), 1) << unwritable.err;
  EXPECT_NE(unwritable.err.find("/proc/self/glint-out"), std::string::npos) << unwritable.err;

  const CliResult bad = run_glint(kFrame + quoted(folder.path() / "b") + " --format tiff");
  EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace
}  // namespace glint::testing
