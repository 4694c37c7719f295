// FramePipeline's linear colour (set_linear_capture, read_linear, FrameReadback::linear_image): the
// tone map's input with the exposure applied, which the renderer's tone map (render/tone_map.h)
// turns into the frame's RGBA8 image, read the same way directly and through the pipelined readback.
#include "gl/gl_check.h"
#include "render/frame_pipeline.h"
#include "render/tone_map.h"
#include "raster_test_scene.h"
#include "support/error_of.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace glint::render {
namespace {

using FramePipelineLinearTest = testing::GlTest;
using testing::camera_looking_down_the_floor;
using testing::mirror_floor_with_wall;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

FramePipelineSettings with_exposure(float exposure) {
  FramePipelineSettings settings;
  settings.resolve.exposure = exposure;
  settings.resolve.tone_map = ToneMap::aces;
  return settings;
}

int largest_difference(const ImageRgba8& a, const ImageRgba8& b) {
  int largest = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (glm::length_t c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a.pixels[i][c]) - int(b.pixels[i][c])));
  return largest;
}

TEST_F(FramePipelineLinearTest, TheLinearColourToneMappedIsTheFinalImageAndCarriesTheExposure) {
  const Scene scene = mirror_floor_with_wall(-4.0f);
  FramePipeline bright(scene, kWidth, kHeight, with_exposure(2.0f));
  EXPECT_NE(testing::error_of([&] { (void)bright.read_linear(); }).find("set_linear_capture"), std::string::npos);
  bright.set_linear_capture(true);
  bright.render(camera_looking_down_the_floor());
  check_gl("frame");
  const ImageRgbaF linear = bright.read_linear();
  ASSERT_EQ(linear.width, kWidth);
  ASSERT_EQ(linear.height, kHeight);
  EXPECT_LE(largest_difference(tone_map_to_rgba8(linear, ToneMap::aces), bright.read_final()), 1);

  // Exposure 1: exactly half the colour (the exposure is a factor of 2: exact in float).
  FramePipeline plain(scene, kWidth, kHeight, with_exposure(1.0f));
  plain.set_linear_capture(true);
  plain.render(camera_looking_down_the_floor());
  const ImageRgbaF half = plain.read_linear();
  int lit = 0;
  for (std::size_t i = 0; i < half.pixels.size(); ++i) {
    EXPECT_EQ(glm::vec3(half.pixels[i]) * 2.0f, glm::vec3(linear.pixels[i])) << i;
    EXPECT_EQ(half.pixels[i].w, 1.0f);
    lit += half.pixels[i].x > 0.0f;
  }
  EXPECT_GT(lit, kWidth * kHeight / 4);
}

TEST_F(FramePipelineLinearTest, ThePipelinedReadbackHoldsTheSameLinearImage) {
  const Scene scene = mirror_floor_with_wall(-4.0f);
  FramePipeline pipeline(scene, kWidth, kHeight, with_exposure(1.0f));
  pipeline.set_linear_capture(true);
  pipeline.render(camera_looking_down_the_floor());
  const std::optional<FrameReadback> readback = pipeline.take_readback(0, /*wait=*/true);
  ASSERT_TRUE(readback.has_value());
  ASSERT_TRUE(readback->linear_image.has_value());
  EXPECT_FALSE(readback->final_image.has_value()) << "no final capture asked for";
  EXPECT_EQ(readback->linear_image->pixels, pipeline.read_linear().pixels) << "same rows, top first";

  pipeline.set_linear_capture(false);
  pipeline.render(camera_looking_down_the_floor());
  const std::optional<FrameReadback> later = pipeline.take_readback(1, /*wait=*/true);
  ASSERT_TRUE(later.has_value());
  EXPECT_FALSE(later->linear_image.has_value());
}

}  // namespace
}  // namespace glint::render
