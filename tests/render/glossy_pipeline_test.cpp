// Glossy reflections in the whole frame (docs/glossy.md): roughness 0 gives the mirror image bit for
// bit, --glossy off is the mirror image whatever the roughness, several samples of a mirror average
// to the one-sample image exactly, a rough surface's reflection changes and loses energy, and the
// denoiser passes mirrors through.
#include "metrics/rmse_psnr.h"
#include "render/frame_pipeline.h"
#include "raster_test_scene.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace glint::render {
namespace {

using GlossyPipelineTest = testing::GlTest;
using testing::camera_looking_down_the_floor;
using testing::mirror_floor_with_wall;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

FramePipelineSettings settings_for(ReflectionMode mode, bool glossy, int spp = 1) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.sampling.glossy = glossy;
  settings.sampling.samples_per_pixel = spp;
  return settings;
}

struct Rendered {
  ImageRgba8 image;
  std::optional<RayTraceFrameStats> rays;
};

// Pixels that differ and the largest channel difference, for the failure messages.
std::string difference(const ImageRgba8& a, const ImageRgba8& b) {
  int pixels = 0, largest = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[i][c]) - int(b.pixels[i][c])));
    pixels += d > 0;
    largest = std::max(largest, d);
  }
  return std::to_string(pixels) + " pixels differ, by up to " + std::to_string(largest);
}

Rendered render(const Scene& scene, const FramePipelineSettings& settings, const FrameState& frame) {
  FramePipeline pipeline(scene, kWidth, kHeight, settings);
  pipeline.render(frame);
  return {pipeline.read_final(), pipeline.ray_trace_stats()};
}

// The test scene's floor and wall as perfect mirrors (raster_test_scene gives them roughness 0.25).
Scene mirror_scene() {
  Scene scene = mirror_floor_with_wall(-4.0f);
  for (Material& material : scene.materials) material.roughness = 0.0f;
  return scene;
}

const Scene& atrium() {
  static const Scene scene = make_preset("atrium-simple");
  return scene;
}

TEST_F(GlossyPipelineTest, RoughnessZeroGivesTheMirrorImageBitForBit) {
  Scene mirrors = atrium();
  for (Material& material : mirrors.materials) material.roughness = 0.0f;
  const FrameState frame = WalkthroughAnimation(atrium()).at(2100);
  for (ReflectionMode mode : {ReflectionMode::ssr, ReflectionMode::hybrid, ReflectionMode::rt}) {
    const ImageRgba8 glossy = render(mirrors, settings_for(mode, true), frame).image;
    // --glossy off: every surface a mirror whatever its roughness, the reflections before glossy ones.
    const ImageRgba8 mirror = render(atrium(), settings_for(mode, false), frame).image;
    EXPECT_TRUE(glossy.pixels == mirror.pixels) << reflection_mode_name(mode) << ": " << difference(glossy, mirror);
    // The atrium's own roughness does change the image (so the comparison above can fail).
    const ImageRgba8 rough = render(atrium(), settings_for(mode, true), frame).image;
    EXPECT_FALSE(rough.pixels == mirror.pixels) << reflection_mode_name(mode);
  }
}

TEST_F(GlossyPipelineTest, SamplesOfAMirrorAverageToTheOneSampleImageExactly) {
  const Scene scene = mirror_scene();
  const Rendered one = render(scene, settings_for(ReflectionMode::rt, true, 1), camera_looking_down_the_floor());
  const Rendered four = render(scene, settings_for(ReflectionMode::rt, true, 4), camera_looking_down_the_floor());
  EXPECT_TRUE(four.image.pixels == one.image.pixels) << difference(four.image, one.image);
  ASSERT_TRUE(one.rays && four.rays);
  EXPECT_GT(one.rays->rays_traced, 0u);
  EXPECT_EQ(four.rays->rays_traced, 4u * one.rays->rays_traced);
}

TEST_F(GlossyPipelineTest, RoughFloorChangesTheReflectionAndOnlyTakesEnergy) {
  Scene scene = mirror_scene();
  const Rendered mirror = render(scene, settings_for(ReflectionMode::rt, true, 1), camera_looking_down_the_floor());
  scene.materials[0].roughness = 0.5f;
  const Rendered rough = render(scene, settings_for(ReflectionMode::rt, true, 16), camera_looking_down_the_floor());
  // A rough floor's reflection is a different image; its samples are weighted by G2/G1 <= 1 (the
  // energy Smith masking takes), so the floor below the wall is nowhere brighter than the mirror's.
  int brighter = 0;
  for (int y = kHeight * 3 / 5; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) brighter += rough.image.at(x, y).y > mirror.image.at(x, y).y + 2;
  EXPECT_EQ(brighter, 0);
  EXPECT_LT(metrics::rmse_psnr(rough.image, mirror.image).psnr, 40.0);
}

TEST_F(GlossyPipelineTest, SsrLeavesSurfacesRougherThanTheCutoffToTheRays) {
  Scene scene = mirror_scene();
  scene.materials[0].roughness = 0.8f;  // the floor
  auto counts = [&](float cutoff) {
    FramePipelineSettings settings = settings_for(ReflectionMode::hybrid, true);
    settings.sampling.roughness_cutoff = cutoff;
    FramePipeline pipeline(scene, kWidth, kHeight, settings);
    pipeline.render(camera_looking_down_the_floor());
    return *pipeline.read_counts();
  };
  const SsrCounts above = counts(0.6f);
  EXPECT_GT(above.reflective, 1000u);
  EXPECT_EQ(above.failed, above.reflective) << "every floor pixel is left to the rays";
  const SsrCounts below = counts(1.0f);
  EXPECT_LT(below.failed, below.reflective) << "with the cutoff above the floor's roughness SSR marches it";
}

TEST_F(GlossyPipelineTest, DenoiserPassesMirrorsThroughLikeTheUnblurredResolve) {
  const Scene scene = mirror_scene();
  FramePipelineSettings blur = settings_for(ReflectionMode::hybrid, true);
  blur.resolve.blur_radius = 0;
  FramePipelineSettings denoise = blur;
  denoise.resolve.denoise = true;
  const ImageRgba8 denoised = render(scene, denoise, camera_looking_down_the_floor()).image;
  const ImageRgba8 unblurred = render(scene, blur, camera_looking_down_the_floor()).image;
  EXPECT_TRUE(denoised.pixels == unblurred.pixels) << difference(denoised, unblurred);
}

}  // namespace
}  // namespace glint::render
