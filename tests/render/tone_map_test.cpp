// render/tone_map.h: the resolve shader's tone map and sRGB encoding (shaders/include/tone_map.glsl)
// compiled as C++, on values worked out by hand. That it equals the GPU's frames is checked end to
// end by tests/app/render_exr_cli_test.cpp.
#include "render/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::testing {
namespace {

using render::ToneMap;
using render::tone_mapped_srgb;

constexpr float kSrgbOfHalf = 0.7353570f;  // 1.055 x 0.5^(1/2.4) - 0.055

TEST(ToneMap, NoneClampsAndEncodesSrgb) {
  const vec3 c = tone_mapped_srgb(vec3(0.5f, 2.0f, -1.0f), ToneMap::none);
  EXPECT_NEAR(c.x, kSrgbOfHalf, 1e-6f);
  EXPECT_NEAR(c.y, 1.0f, 1e-6f);
  EXPECT_EQ(c.z, 0.0f);
  // The linear segment below 0.0031308.
  EXPECT_NEAR(tone_mapped_srgb(vec3(0.001f), ToneMap::none).x, 0.01292f, 1e-7f);
}

TEST(ToneMap, ReinhardMapsOneToAHalf) {
  EXPECT_NEAR(tone_mapped_srgb(vec3(1.0f), ToneMap::reinhard).x, kSrgbOfHalf, 1e-6f);
  EXPECT_NEAR(tone_mapped_srgb(vec3(3.0f), ToneMap::reinhard).y, 1.055f * std::pow(0.75f, 1.0f / 2.4f) - 0.055f, 1e-6f);
}

TEST(ToneMap, AcesIsNarkowiczsFit) {
  // 0.18 x (2.51 x 0.18 + 0.03) / (0.18 x (2.43 x 0.18 + 0.59) + 0.14) = 0.266899, encoded 0.553458.
  EXPECT_NEAR(tone_mapped_srgb(vec3(0.18f), ToneMap::aces).x, 0.553458f, 2e-6f);
  EXPECT_EQ(tone_mapped_srgb(vec3(0.0f), ToneMap::aces).x, 0.0f);
  EXPECT_NEAR(tone_mapped_srgb(vec3(1e4f), ToneMap::aces).x, 1.0f, 1e-6f);  // 2.51 / 2.43 > 1, clamped
}

TEST(ToneMap, ToRgba8QuantisesEveryPixelOpaque) {
  ImageRgbaF linear(2, 1);
  linear.at(0, 0) = vec4(0.18f, 0.0f, 1e4f, 0.0f);
  linear.at(1, 0) = vec4(1.0f, 1.0f, 1.0f, 0.5f);
  const ImageRgba8 picture = render::tone_map_to_rgba8(linear, ToneMap::aces);
  EXPECT_EQ(picture.at(0, 0), glm::u8vec4(141, 0, 255, 255));  // 0.553458 x 255 = 141.13
  EXPECT_EQ(picture.at(1, 0).w, 255);
}

}  // namespace
}  // namespace glint::testing
