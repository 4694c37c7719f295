// Hybrid's trusted SSR pixels against the ray-traced reference on the sponza scene with every
// material reflective (scenes/sponza-all-reflective.scene.json, reflectivity 0.35): where SSR kept
// its hit, the frame must be what rt draws there, within a stated tolerance. Skipped without the
// shared assets (GLINT_ASSETS or ../shared/assets).
#include "render/frame_pipeline.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"

#include "../gl/gl_test_context.h"
#include "support/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace glint::render {
namespace {

std::filesystem::path assets_folder() {
  const char* assets = std::getenv("GLINT_ASSETS");
  return assets != nullptr && *assets != '\0' ? std::filesystem::path(assets)
                                              : glint::testing::source_dir() / ".." / "shared" / "assets";
}

// No blur (it mixes SSR and traced neighbours), no fade, no tone curve: a pixel's colour is its
// own lit colour plus reflectivity x its own reflection.
FramePipelineSettings unfiltered(ReflectionMode mode) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;
  settings.resolve.tone_map = ToneMap::none;
  return settings;
}

using SsrSponzaTrustTest = glint::testing::GlTest;

// Tolerance (8-bit final colour, largest channel difference, at the pixels SSR trusted): mean <= 2.5
// and at most 3 % of them more than 16 apart. What remains is what screen space cannot match
// exactly even where its hit is right: the lit colour is the camera's view of the hit (its
// highlight and texture filtering), interpolated between pixel centres.
// (Measured at 320x180: mean 1.714, 2.4 % over 16 on llvmpipe; 1.766 and 2.1 % with the hit pixel's
// own colour before the colour was taken where the ray meets the surface, too close to tell the two
// apart here: SsrPassTest.TheColourOfAHitIsTakenWhereTheRayMeetsTheSurface does; the former march's
// tolerances: 3.06 and 3.5 %.)
// About 6 s on two cores (the scene's load and three frames); skipped where CI has no assets.
TEST_F(SsrSponzaTrustTest, HybridsTrustedPixelsEqualRtOnTheAllReflectiveFrame) {
  if (!std::filesystem::exists(assets_folder() / "sponza_dabrovic" / "sponza.obj"))
    GTEST_SKIP() << assets_folder() << " has no sponza_dabrovic/sponza.obj (set GLINT_ASSETS to the assets folder)";
  LoadOptions options;
  options.assets_dir = assets_folder();
  const Scene scene =
      load_scene((glint::testing::source_dir() / "scenes" / "sponza-all-reflective.scene.json").string(), options);
  const FrameState frame = WalkthroughAnimation(scene).at(2100);
  constexpr int width = 320, height = 180;

  FramePipeline rt(scene, width, height, unfiltered(ReflectionMode::rt));
  rt.render(frame);
  const ImageRgba8 rt_image = rt.read_final();

  struct Agreement {
    int trusted = 0;
    int far_apart = 0;  // more than 16 apart
    double mean = 0.0;
  };
  const auto agreement = [&](const SsrSettings& ssr) {
    FramePipelineSettings settings = unfiltered(ReflectionMode::hybrid);
    settings.ssr = ssr;
    FramePipeline hybrid(scene, width, height, settings);
    hybrid.render(frame);
    const ImageRgba8 image = hybrid.read_final();
    std::vector<bool> failed;
    for (const DebugView& view : hybrid.read_debug_views())
      if (view.name == "failure_mask")
        for (const auto& p : view.image.pixels) failed.push_back(p.x > 127);
    EXPECT_EQ(failed.size(), image.pixels.size());
    Agreement result;
    for (std::size_t i = 0; i < failed.size() && i < image.pixels.size(); ++i) {
      if (failed[i]) continue;
      const auto a = image.pixels[i], b = rt_image.pixels[i];
      const int difference = std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
      ++result.trusted;
      result.mean += difference;
      result.far_apart += difference > 16;
    }
    result.mean /= std::max(result.trusted, 1);
    return result;
  };

  const Agreement trusted = agreement(SsrSettings{});
  std::printf("sponza all reflective, frame 2100, 320x180: %d trusted pixels, mean difference %.3f, %d over 16\n",
              trusted.trusted, trusted.mean, trusted.far_apart);
  ASSERT_GT(trusted.trusted, width * height / 5) << "SSR must keep a good part of the frame";
  EXPECT_LE(trusted.mean, 2.5) << "mean difference at " << trusted.trusted << " trusted pixels";
  EXPECT_LE(trusted.far_apart * 100, trusted.trusted * 3)
      << trusted.far_apart << " of " << trusted.trusted << " trusted pixels differ by more than 16";

  // The control: the former model's tolerances (surfaces 6 % of their depth thick, about the fixed
  // 0.5 world units here; every hidden ray walks on; no silhouette or grazing test) trust pixels
  // that rt draws differently, and fail the tolerance.
  SsrSettings former;
  former.thickness = 0.06f;
  former.empty_behind = former.thickness;
  former.silhouette_footprints = 1e6f;
  former.min_hit_cosine = 0.0f;
  const Agreement loose = agreement(former);
  EXPECT_GT(loose.mean, 2.5) << "the control must miss the tolerance";
  EXPECT_GT(loose.far_apart * 100, loose.trusted * 3) << "the control must miss the tolerance";
}

}  // namespace
}  // namespace glint::render
