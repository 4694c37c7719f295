// The live settings table of `glint view`: names, values and ranges are checked as the CLI checks
// its flags, and every row reaches the RenderOptions field the renderer reads.
#include "viewer/viewer_settings.h"

#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::viewer {
namespace {

using glint::testing::error_of;

TEST(ViewerSettings, SetsTheFieldsRenderPipelineSettingsReads) {
  RenderOptions options;
  set_viewer_setting(options, "reflections", "rt");
  set_viewer_setting(options, "backend", "embree");
  set_viewer_setting(options, "ssr-max-steps", "64");
  set_viewer_setting(options, "exposure", "1.5");
  set_viewer_setting(options, "shadows", "cube");
  EXPECT_EQ(options.reflections, "rt");
  EXPECT_EQ(options.backend, "embree");
  EXPECT_EQ(options.ssr_max_steps, 64);
  EXPECT_FLOAT_EQ(options.exposure, 1.5f);
  const render::FramePipelineSettings settings = render_pipeline_settings(options);
  EXPECT_EQ(settings.reflections, render::ReflectionMode::rt);
  EXPECT_EQ(settings.ssr.max_steps, 64);
  EXPECT_EQ(settings.shadows.method, render::ShadowMethod::cube);
}

TEST(ViewerSettings, BadNamesValuesAndRangesAreOneClearError) {
  RenderOptions options;
  EXPECT_NE(error_of([&] { set_viewer_setting(options, "reflection", "rt"); }).find("unknown setting \"reflection\""),
            std::string::npos);
  const std::string choice = error_of([&] { set_viewer_setting(options, "reflections", "raytraced"); });
  EXPECT_NE(choice.find("off, ssr, hybrid, rt"), std::string::npos) << choice;
  EXPECT_NE(error_of([&] { set_viewer_setting(options, "ssr-max-steps", "5000"); }).find("outside 1 to 4096"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_viewer_setting(options, "blur-radius", "2.5"); }).find("not an integer"),
            std::string::npos);
  EXPECT_NE(error_of([&] { set_viewer_setting(options, "exposure", "bright"); }).find("not a number"),
            std::string::npos);
  EXPECT_EQ(options.reflections, RenderOptions().reflections) << "a refused value changes nothing";
}

TEST(ViewerSettings, EveryRowReadsBackAndCountsForTheRebuild) {
  for (const ViewerSetting& setting : viewer_settings()) {
    RenderOptions options;
    const std::string value = setting.choices.empty() ? fmt::format("{}", setting.min) : setting.choices.back();
    set_viewer_setting(options, setting.name, value);
    EXPECT_EQ(viewer_setting_text(options, setting), value) << setting.name;
    const bool changed = !same_viewer_settings(options, RenderOptions());
    EXPECT_EQ(changed, value != viewer_setting_text(RenderOptions(), setting)) << setting.name;
  }
  RenderOptions resized;
  resized.width = 320;
  EXPECT_FALSE(same_viewer_settings(resized, RenderOptions()));
}

// The panel clamps every number to its row's range, so both ends must be values the renderer takes:
// a wider range offers values that fail the rebuild (ssr-thickness once went to 100, while the
// thickness is a fraction of view depth in (0, 1]).
TEST(ViewerSettings, EveryNumberRowsRangeIsOneTheRendererTakes) {
  for (const ViewerSetting& setting : viewer_settings()) {
    if (!setting.choices.empty()) continue;
    for (const double end : {setting.min, setting.max}) {
      RenderOptions options;
      set_viewer_setting(options, setting.name, fmt::format("{}", end));
      EXPECT_NO_THROW(render_pipeline_settings(options)) << setting.name << " = " << end;
    }
  }
  const ViewerSetting* thickness = find_viewer_setting("ssr-thickness");
  ASSERT_NE(thickness, nullptr);
  EXPECT_GT(thickness->min, 0.0);
  EXPECT_EQ(thickness->max, 1.0);
  // Shown to four places, so that the range's low end (0.0001) is not shown as 0.
  EXPECT_STREQ(thickness->format, "%.4f");
}

TEST(ViewerSettings, CpuBackendsAreAlwaysAvailable) {
  const std::vector<std::string> backends = available_backends();
  ASSERT_GE(backends.size(), 2u);
  EXPECT_EQ(backends[0], "cpu");
  EXPECT_EQ(backends[1], "embree");
}

}  // namespace
}  // namespace glint::viewer
