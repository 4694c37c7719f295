// The whole raster pipeline on the built-in atrium: a plausible image with shadows, and the passes
// reported to the GPU timer under the names timings.csv uses.
#include "gl/gl_test_context.h"
#include "render/raster_pipeline.h"
#include "scene/camera_path.h"
#include "scene/presets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace glint {
namespace {

using render::RasterOutput;
using render::RasterPipeline;
using RasterPipelineTest = testing::GlTest;

TEST_F(RasterPipelineTest, AtriumSimpleFrame2100HasLightAndShadowAndNoNonFinitePixels) {
  const Scene scene = make_preset("atrium-simple");
  const WalkthroughAnimation animation(scene);
  ASSERT_GT(animation.frame_count(), 2100);
  RasterPipeline raster(scene, 96, 54);
  GpuTimer timer;
  timer.begin_frame();
  raster.render(animation.at(2100), &timer);
  timer.end_frame();
  timer.wait_for_all();

  const ImageRgbaF lit = raster.read_rgbaf(RasterOutput::Lit);
  const ImageRgbaF mask = raster.read_rgbaf(RasterOutput::ShadowMask);
  const ImageRgbaF id = raster.read_rgbaf(RasterOutput::MaterialId);
  int non_finite = 0, geometry = 0, shadowed = 0, lit_pixels = 0;
  float lowest = 1e30f, highest = -1e30f;
  for (std::size_t i = 0; i < lit.pixels.size(); ++i) {
    const vec4 p = lit.pixels[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) || !std::isfinite(p.w)) {
      ++non_finite;
      continue;
    }
    const float luminance = 0.2126f * p.x + 0.7152f * p.y + 0.0722f * p.z;
    lowest = std::min(lowest, luminance);
    highest = std::max(highest, luminance);
    if (id.pixels[i].x == 0.0f) continue;
    ++geometry;
    shadowed += mask.pixels[i].x < 0.5f;
    lit_pixels += mask.pixels[i].x > 0.5f;
  }
  EXPECT_EQ(non_finite, 0);
  EXPECT_GT(highest - lowest, 0.1f);
  EXPECT_GT(geometry, 96 * 54 / 2);  // frame 2100 looks down the hall
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit_pixels, 20);

  const std::vector<FrameTimes> frames = timer.take_completed();
  ASSERT_EQ(frames.size(), 1u);
  ASSERT_EQ(frames[0].passes.size(), 3u);
  EXPECT_EQ(frames[0].passes[0].name, "gbuffer");
  EXPECT_EQ(frames[0].passes[1].name, "shadow");
  EXPECT_EQ(frames[0].passes[2].name, "light");
}

}  // namespace
}  // namespace glint
