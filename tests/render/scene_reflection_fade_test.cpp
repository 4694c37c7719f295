// The reflections' distance fade follows the scene's size (render/scene_reflection_fade.h): the
// atrium keeps the paper's 15 and 30 world units to the bit, a copy scaled by 1000 or 0.001 or moved
// far away gets the same fade relative to its size (and, scaled, the same picture), and a scene's
// own "reflection_fade" is taken as given.
#include "render/frame_pipeline.h"
#include "render/scene_reflection_fade.h"
#include "raster_test_scene.h"
#include "transformed_scene.h"
#include "scene/presets.h"
#include "scene/procedural/atrium.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

namespace glint::render {
namespace {

using testing::image_difference;
using testing::transformed;

TEST(SceneReflectionFade, AtriumKeepsThePapersFadeExactly) {
  {  // atrium-simple: `atrium` is the same building with denser creatures, and make_atrium sets both
    Scene atrium = procedural::make_atrium(procedural::AtriumDetail::simple);
    const DistanceFade fade = scene_reflection_fade(atrium);
    EXPECT_EQ(fade.start, 15.0f);
    EXPECT_EQ(fade.end, 30.0f);
    // The size rule's fractions come from the atrium: without its own fade it gets nearly the same.
    const float diagonal = length(atrium.world_bounds().extent());
    EXPECT_NEAR(diagonal, 46.1f, 0.05f);
    atrium.reflection_fade.reset();
    const DistanceFade rule = scene_reflection_fade(atrium);
    EXPECT_NEAR(rule.start, 15.0f, 0.03f);
    EXPECT_NEAR(rule.end, 30.0f, 0.06f);
  }
}

TEST(SceneReflectionFade, IsTheSameFractionOfAnyScenesDiagonal) {
  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const float diagonal = length(scene.world_bounds().extent());
  const DistanceFade fade = scene_reflection_fade(scene);
  EXPECT_FLOAT_EQ(fade.start, kFadeStartFraction * diagonal);
  EXPECT_FLOAT_EQ(fade.end, kFadeEndFraction * diagonal);

  const DistanceFade large = scene_reflection_fade(transformed(scene, 1000.0f, vec3(0.0f)));
  EXPECT_NEAR(large.start, 1000.0f * fade.start, 1e-5f * large.start);
  EXPECT_NEAR(large.end, 1000.0f * fade.end, 1e-5f * large.end);
  const DistanceFade small = scene_reflection_fade(transformed(scene, 0.001f, vec3(0.0f)));
  EXPECT_NEAR(small.start, 0.001f * fade.start, 1e-5f * small.start);
  const DistanceFade far = scene_reflection_fade(transformed(scene, 1.0f, vec3(1.0e5f, -2.0e4f, 1.0e5f)));
  EXPECT_NEAR(far.start, fade.start, 1e-3f * fade.start) << "moving the scene does not change its size";
  EXPECT_NEAR(far.end, fade.end, 1e-3f * fade.end);
}

TEST(SceneReflectionFade, SceneFilesFadeAndTheSettingsOwnAreKept) {
  Scene scene = testing::mirror_floor_with_wall(-4.0f);
  scene.reflection_fade = DistanceFade{2.0f, 4.5f};
  const DistanceFade given = scene_reflection_fade(scene);
  EXPECT_EQ(given.start, 2.0f);
  EXPECT_EQ(given.end, 4.5f);

  ResolveSettings settings;
  const ResolveSettings fitted = with_scene_fade(settings, scene);
  EXPECT_EQ(fitted.fade_start, 2.0f);
  EXPECT_EQ(fitted.fade_end, 4.5f);
  settings.fade_end = 0.0f;  // off stays off
  EXPECT_EQ(with_scene_fade(settings, scene).fade_end, 0.0f);
  settings.fade_start = 7.0f;
  settings.fade_end = 9.0f;
  settings.fade_from_scene = false;  // taken as given
  EXPECT_EQ(with_scene_fade(settings, scene).fade_start, 7.0f);
  EXPECT_EQ(with_scene_fade(settings, scene).fade_end, 9.0f);
}

using SceneReflectionFadeGlTest = testing::GlTest;

constexpr int kWidth = 160;
constexpr int kHeight = 90;
constexpr int kFrame = 2100;  // the atrium's floor reflects the hall and its far end

ImageRgba8 render_atrium(const Scene& scene, bool fade_from_scene) {
  FramePipelineSettings settings;
  settings.reflections = ReflectionMode::hybrid;
  settings.resolve.fade_from_scene = fade_from_scene;
  FramePipeline pipeline(scene, kWidth, kHeight, settings);
  pipeline.render(WalkthroughAnimation(scene).at(kFrame));
  return pipeline.read_final();
}

// A copy of the atrium at another scale renders the same picture, reflections and their fade
// included, up to float noise: single pixels on edges and fine texture detail (0.6 % of them at
// x1000 on llvmpipe). The copy scaled by 0.001 also guards the clip range, whose floors in world
// units once clipped it away (frame_constants.h). Copies moved far away: far_from_origin_test.cpp.
TEST_F(SceneReflectionFadeGlTest, AtriumScaledRendersTheSameReflections) {
  Scene atrium = make_preset("atrium-simple");
  atrium.reflection_fade.reset();  // the size rule, not the preset's own fade
  const ImageRgba8 original = render_atrium(atrium, true);
  constexpr int kNoise = kWidth * kHeight / 100;
  for (const float scale : {1000.0f, 0.001f}) {
    const Scene other = transformed(atrium, scale, vec3(0.0f));
    const testing::ImageDifference fitted = image_difference(original, render_atrium(other, true));
    EXPECT_LE(fitted.pixels, kNoise) << "scaled by " << scale << ": " << fitted.text();
  }
  // The control: with the fade at fixed world distances (15..30) the copy scaled by 1000 loses the
  // floor's reflections, so the comparison above can fail.
  const testing::ImageDifference fixed =
      image_difference(original, render_atrium(transformed(atrium, 1000.0f, vec3(0.0f)), false));
  EXPECT_GT(fixed.pixels, 10 * kNoise) << "fade fixed at 15..30 world units: " << fixed.text();
}

}  // namespace
}  // namespace glint::render
