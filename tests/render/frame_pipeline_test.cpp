// The whole frame (raster, SSR, resolve) on scenes built in code: what SSR finds and misses through
// the real G-buffer, the counters against the mask, and mode off against ssr.
#include "gl/gl_check.h"
#include "render/frame_pipeline.h"
#include "render/render_targets.h"
#include "render/texture_readback.h"
#include "raster_test_scene.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::render {
namespace {

using FramePipelineTest = testing::GlTest;
using testing::camera_looking_down_the_floor;
using testing::mirror_floor_with_wall;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

FramePipelineSettings ssr_without_blur() {
  FramePipelineSettings settings;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;  // no fade: the reflection enters the composite at full weight
  settings.resolve.tone_map = ToneMap::none;
  return settings;
}

struct MaskStats {
  int failed = 0;
  int red_hits = 0;  // pixels whose SSR reflection is clearly the red wall
};

MaskStats mask_stats(const FramePipeline& pipeline) {
  MaskStats stats;
  for (const DebugView& view : pipeline.read_debug_views()) {
    if (view.name == "failure_mask")
      for (const auto& p : view.image.pixels) stats.failed += p.x > 127;
    if (view.name == "ssr_reflection")
      for (const auto& p : view.image.pixels) stats.red_hits += p.x > 100 && p.y < 20 && p.z < 20;
  }
  return stats;
}

TEST_F(FramePipelineTest, WallInViewIsReflectedByTheFloorAndCountsMatchTheMask) {
  const Scene scene = mirror_floor_with_wall(-4.0f);
  FramePipeline pipeline(scene, kWidth, kHeight, ssr_without_blur());
  pipeline.render(camera_looking_down_the_floor());
  check_gl("frame");

  const auto counts = pipeline.read_counts();
  ASSERT_TRUE(counts.has_value());
  const MaskStats stats = mask_stats(pipeline);
  EXPECT_EQ(static_cast<int>(counts->failed), stats.failed) << "the failed-pixel counter is the mask's sum";
  EXPECT_GT(counts->reflective, 0u);
  // 48 on llvmpipe; 70 with silhouette_footprints 2: the hits on the wall's bottom row, at its
  // right-angled crease with the floor, now fail (docs/ssr.md "Silhouettes, creases and steps").
  EXPECT_GT(stats.red_hits, 40) << "the wall's mirror image on the floor comes from SSR hits";

  // In the final image, the floor just below the wall's base is red (its reflection), while the same
  // floor with reflections off is dark grey.
  FramePipelineSettings off = ssr_without_blur();
  off.reflections = ReflectionMode::off;
  FramePipeline unreflected(scene, kWidth, kHeight, off);
  unreflected.render(camera_looking_down_the_floor());
  EXPECT_FALSE(unreflected.read_counts().has_value()) << "nothing is counted when SSR does not run";
  const ImageRgba8 with = pipeline.read_final();
  const ImageRgba8 without = unreflected.read_final();
  int redder = 0;
  for (std::size_t i = 0; i < with.pixels.size(); ++i)
    redder += with.pixels[i].x > without.pixels[i].x + 40;
  EXPECT_GE(redder, stats.red_hits / 2) << "SSR hits reach the final image";
}

TEST_F(FramePipelineTest, WallBehindTheCameraIsNotReflectedAndItsPixelsFail) {
  const Scene scene = mirror_floor_with_wall(10.0f);
  FramePipeline pipeline(scene, kWidth, kHeight, ssr_without_blur());
  pipeline.render(camera_looking_down_the_floor());
  const auto counts = pipeline.read_counts();
  ASSERT_TRUE(counts.has_value());
  const MaskStats stats = mask_stats(pipeline);
  EXPECT_EQ(stats.red_hits, 0) << "screen space cannot see what is behind the camera";
  EXPECT_EQ(static_cast<int>(counts->failed), stats.failed);
  // Every reflective pixel sees either sky or the off-screen wall: all of them fail.
  EXPECT_EQ(counts->failed, counts->reflective);
}

TEST_F(FramePipelineTest, AtriumFramesAreNotConstantAndDiffer) {
  Scene scene = make_preset("atrium-simple");
  const WalkthroughAnimation animation(scene);
  FramePipeline pipeline(scene, kWidth, kHeight);
  pipeline.render(animation.at(2100));
  const ImageRgba8 first = pipeline.read_final();
  pipeline.render(animation.at(4400));
  const ImageRgba8 second = pipeline.read_final();
  const auto distinct = [](const ImageRgba8& image) {
    int changes = 0;
    for (std::size_t i = 1; i < image.pixels.size(); ++i) changes += image.pixels[i] != image.pixels[i - 1];
    return changes;
  };
  EXPECT_GT(distinct(first), static_cast<int>(first.pixels.size() / 4)) << "a rendered frame is not a flat image";
  int differing = 0;
  for (std::size_t i = 0; i < first.pixels.size(); ++i) differing += first.pixels[i] != second.pixels[i];
  EXPECT_GT(differing, static_cast<int>(first.pixels.size() / 2)) << "the camera moved between the frames";
}

}  // namespace
}  // namespace glint::render
