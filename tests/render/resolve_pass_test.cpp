// Resolve: distance fade, normalised separable Gaussian blur and composite + tone map + sRGB,
// each checked against its formula evaluated on the CPU.
#include "render/resolve_pass.h"

#include "gl/gl_test_context.h"
#include "render/render_targets.h"
#include "render/synthetic_gbuffer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace glint::render {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;
constexpr std::size_t kPixels = static_cast<std::size_t>(kWidth) * kHeight;

std::size_t index(int x, int y) { return static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x); }

ResolveSettings plain_settings() {
  ResolveSettings s;
  s.fade_end = 0.0f;  // off
  s.blur_radius = 0;
  s.exposure = 1.0f;
  s.tone_map = ToneMap::none;
  return s;
}

struct ResolveImages {
  GlTexture lit;
  GlTexture albedo_reflectivity;
  GlTexture reflection;
};

ResolveImages upload_images(const std::vector<vec4>& lit, const std::vector<glm::u8vec4>& albedo,
                            const std::vector<vec4>& reflection) {
  return {testing::upload_rgba(kLitFormat, kWidth, kHeight, lit), testing::upload_rgba8(kWidth, kHeight, albedo),
          testing::upload_rgba(kReflectionFormat, kWidth, kHeight, reflection)};
}

double srgb_encode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double tone_map_cpu(double c, ToneMap tone_map) {
  c = std::max(c, 0.0);
  switch (tone_map) {
    case ToneMap::none: return std::min(c, 1.0);
    case ToneMap::reinhard: return c / (1.0 + c);
    case ToneMap::aces: return std::clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
  }
  return c;
}

double gaussian(int i, double sigma) { return std::exp(-double(i * i) / (2.0 * sigma * sigma)); }

using ResolvePassTest = glint::testing::GlTest;

TEST_F(ResolvePassTest, RadiusZeroWithoutFadeLeavesTheReflectionBitIdentical) {
  std::mt19937 rng(5);
  std::vector<std::uint16_t> halves(kPixels * 4);
  for (std::size_t p = 0; p < kPixels; ++p) {
    const bool found = rng() % 4 != 0;  // a quarter of the pixels found nothing: all zero
    for (std::size_t c = 0; c < 4; ++c) {
      // Positive normal half floats: exponent 1..29, any mantissa.
      const auto exponent = static_cast<std::uint16_t>(1 + rng() % 29);
      const auto mantissa = static_cast<std::uint16_t>(rng() % 1024);
      halves[p * 4 + c] = found ? static_cast<std::uint16_t>(exponent << 10 | mantissa) : 0;
    }
  }
  const GlTexture reflection = testing::upload_rgba16f_bits(kWidth, kHeight, halves);
  ReflectionBlurPass blur(kWidth, kHeight);
  blur.run(reflection.id(), plain_settings());
  EXPECT_EQ(testing::read_rgba16f_bits(blur.output(), kWidth, kHeight), halves);
}

TEST_F(ResolvePassTest, BlurSpreadsABrightPixelSymmetricallyWithGaussianWeights) {
  constexpr int radius = 3;
  const double sigma = 0.5 * radius;
  const int cx = 30, cy = 20;
  std::vector<vec4> reflection(kPixels, vec4(0.0f, 0.0f, 0.0f, 1.0f));  // every pixel found a (black) reflection
  reflection[index(cx, cy)] = vec4(1.0f, 2.0f, 4.0f, 1.0f);
  const GlTexture texture = testing::upload_rgba(kReflectionFormat, kWidth, kHeight, reflection);
  ReflectionBlurPass blur(kWidth, kHeight);
  ResolveSettings settings = plain_settings();
  settings.blur_radius = radius;
  blur.run(texture.id(), settings);
  const std::vector<vec4> out = testing::read_rgba_float(blur.output(), kWidth, kHeight);

  double kernel = 0.0;
  for (int i = -radius; i <= radius; ++i) kernel += gaussian(i, sigma);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const int dx = x - cx, dy = y - cy;
      const bool inside = std::abs(dx) <= radius && std::abs(dy) <= radius;
      const double weight = inside ? gaussian(dx, sigma) * gaussian(dy, sigma) / (kernel * kernel) : 0.0;
      const vec4 v = out[index(x, y)];
      ASSERT_NEAR(v.x, weight * 1.0, 2e-3 * weight + 1e-6) << dx << "," << dy;
      ASSERT_NEAR(v.y, weight * 2.0, 4e-3 * weight + 1e-6) << dx << "," << dy;
      ASSERT_NEAR(v.z, weight * 4.0, 8e-3 * weight + 1e-6) << dx << "," << dy;
      ASSERT_EQ(v.w, 1.0f) << "the distance passes through";
      if (inside) {
        const vec4 mirrored = out[index(cx - dx, cy - dy)];
        const vec4 transposed = out[index(cx + dy, cy + dx)];
        EXPECT_NEAR(v.x, mirrored.x, 1e-3 * v.x) << dx << "," << dy;
        EXPECT_NEAR(v.x, transposed.x, 1e-3 * v.x) << dx << "," << dy;
      }
    }
  }
  EXPECT_GT(out[index(cx, cy)].x, out[index(cx + 1, cy)].x);
  EXPECT_GT(out[index(cx + 1, cy)].x, out[index(cx + 3, cy)].x);
}

TEST_F(ResolvePassTest, BlurNeitherDarkensNorBleedsAcrossPixelsWithoutAReflection) {
  const vec4 colour(0.5f, 0.25f, 1.0f, 2.0f);
  std::vector<vec4> reflection(kPixels, vec4(0.0f));
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth / 2; ++x) reflection[index(x, y)] = colour;
  const GlTexture texture = testing::upload_rgba(kReflectionFormat, kWidth, kHeight, reflection);
  ReflectionBlurPass blur(kWidth, kHeight);
  ResolveSettings settings = plain_settings();
  settings.blur_radius = 6;
  blur.run(texture.id(), settings);
  const std::vector<vec4> out = testing::read_rgba_float(blur.output(), kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const vec4 v = out[index(x, y)];
      if (x >= kWidth / 2) {
        ASSERT_EQ(v, vec4(0.0f)) << "reflection bled into " << x << "," << y;
      } else {
        ASSERT_NEAR(v.x, colour.x, 1e-3f) << x << "," << y;
        ASSERT_NEAR(v.y, colour.y, 1e-3f) << x << "," << y;
        ASSERT_NEAR(v.z, colour.z, 1e-3f) << x << "," << y;
        ASSERT_EQ(v.w, colour.w);
      }
    }
  }
}

TEST_F(ResolvePassTest, FadeIsMonotoneInTheReflectedDistance) {
  for (const int radius : {0, 2}) {
    // Distance grows along x (0.5 .. 32 world units); a white reflection on a black, fully
    // reflective surface, so the final image is the faded reflection itself.
    std::vector<vec4> reflection(kPixels), lit(kPixels, vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) reflection[index(x, y)] = vec4(1.0f, 1.0f, 1.0f, 0.5f * float(x + 1));
    const ResolveImages images =
        upload_images(lit, std::vector<glm::u8vec4>(kPixels, glm::u8vec4(128, 128, 128, 255)), reflection);
    ResolveSettings settings = plain_settings();
    settings.fade_start = 5.0f;
    settings.fade_end = 20.0f;
    settings.blur_radius = radius;
    ResolvePass resolve(kWidth, kHeight, settings);
    resolve.run({.lit = images.lit.id(), .albedo_reflectivity = images.albedo_reflectivity.id(), .reflection = images.reflection.id()});
    const std::vector<vec4> faded = testing::read_rgba_float(resolve.blurred_reflection(), kWidth, kHeight);
    const std::vector<glm::u8vec4> final_image = testing::read_rgba8(resolve.final_image(), kWidth, kHeight);
    const int y = kHeight / 2;
    for (int x = 0; x < kWidth; ++x) {
      const float distance = 0.5f * float(x + 1);
      const float expected = reflection_fade(distance, settings);
      if (radius == 0) {
        EXPECT_NEAR(faded[index(x, y)].x, expected, 1e-3f) << "distance " << distance;
      }
      if (distance <= settings.fade_start) {
        EXPECT_EQ(expected, 1.0f);
      }
      // With a blur, pixels just past fade_end still gather faded neighbours nearer than it.
      const float blur_reach = 0.5f * float(radius);
      if (distance >= settings.fade_end + blur_reach) {
        EXPECT_EQ(expected, 0.0f);
        EXPECT_EQ(faded[index(x, y)].x, 0.0f) << "distance " << distance;
        EXPECT_EQ(final_image[index(x, y)].x, 0) << "distance " << distance;
      }
      if (x > 0) {
        EXPECT_LE(faded[index(x, y)].x, faded[index(x - 1, y)].x) << "radius " << radius << " distance " << distance;
        EXPECT_LE(final_image[index(x, y)].x, final_image[index(x - 1, y)].x) << "distance " << distance;
        EXPECT_LE(expected, reflection_fade(distance - 0.5f, settings));
      }
    }
    EXPECT_EQ(final_image[index(0, y)].x, 255);
  }
}

// lit + reflectivity x reflection, exposure, tone map, sRGB: against the CPU formula at every pixel.
class ResolveCompositeTest : public glint::testing::GlTest, public ::testing::WithParamInterface<ToneMap> {};

TEST_P(ResolveCompositeTest, FinalIsTheToneMappedSrgbEncodedSum) {
  std::mt19937 rng(11);
  // Multiples of 1/256 below 2 are exact in half floats, so the CPU sees what the GPU loads.
  const auto value = [&] { return static_cast<float>(rng() % 400) / 256.0f; };
  std::vector<vec4> lit(kPixels), reflection(kPixels);
  std::vector<glm::u8vec4> albedo(kPixels);
  for (std::size_t p = 0; p < kPixels; ++p) {
    lit[p] = vec4(value(), value(), value(), 1.0f);
    albedo[p] = glm::u8vec4(200, 100, 50, static_cast<std::uint8_t>(rng() % 256));
    const bool found = rng() % 3 != 0;
    reflection[p] = found ? vec4(value(), value(), value(), 1.0f + float(rng() % 10)) : vec4(0.0f);
  }
  const ResolveImages images = upload_images(lit, albedo, reflection);
  ResolveSettings settings = plain_settings();
  settings.tone_map = GetParam();
  settings.exposure = GetParam() == ToneMap::none ? 1.0f : 1.5f;
  ResolvePass resolve(kWidth, kHeight, settings);
  resolve.run({.lit = images.lit.id(), .albedo_reflectivity = images.albedo_reflectivity.id(), .reflection = images.reflection.id()});
  const std::vector<glm::u8vec4> out = testing::read_rgba8(resolve.final_image(), kWidth, kHeight);
  int clipped = 0;
  for (std::size_t p = 0; p < kPixels; ++p) {
    const double reflectivity = albedo[p].w / 255.0;
    for (int c = 0; c < 3; ++c) {
      const double radiance = settings.exposure * (double(lit[p][c]) + reflectivity * double(reflection[p][c]));
      clipped += radiance > 1.0;
      const double expected = 255.0 * srgb_encode(tone_map_cpu(radiance, settings.tone_map));
      ASSERT_NEAR(double(out[p][c]), expected, 1.0) << "pixel " << p << " channel " << c << " radiance " << radiance;
    }
    ASSERT_EQ(out[p].w, 255);
  }
  EXPECT_GT(clipped, 0) << "the data must exercise the tone map above 1";
}

INSTANTIATE_TEST_SUITE_P(ToneMaps, ResolveCompositeTest,
                         ::testing::Values(ToneMap::none, ToneMap::reinhard, ToneMap::aces),
                         [](const auto& param_info) { return std::string(tone_map_name(param_info.param)); });

TEST_F(ResolvePassTest, SettingsAndInputsAreChecked) {
  using glint::testing::error_of;
  EXPECT_EQ(tone_map_from_name("aces"), ToneMap::aces);
  EXPECT_NE(error_of([] { tone_map_from_name("filmic"); }).find("known: none, reinhard, aces"), std::string::npos);
  ResolveSettings s;
  s.blur_radius = 40;
  EXPECT_NE(error_of([&] { validate(s); }).find("blur_radius"), std::string::npos);
  s = {};
  s.fade_start = 30.0f;
  s.fade_end = 10.0f;
  EXPECT_NE(error_of([&] { validate(s); }).find("fade_start"), std::string::npos);
  s.fade_end = 0.0f;  // fade off: fade_start is ignored
  EXPECT_NO_THROW(validate(s));
  s = {};
  s.exposure = 0.0f;
  EXPECT_NE(error_of([&] { ResolvePass pass(8, 8, s); }).find("exposure"), std::string::npos);

  ResolvePass pass(kWidth, kHeight);
  const GlTexture lit = create_texture_2d(kLitFormat, kWidth, kHeight);
  const GlTexture albedo = create_texture_2d(kAlbedoReflectivityFormat, kWidth, kHeight);
  const GlTexture wrong = create_texture_2d(GL_RGBA8, kWidth, kHeight);
  EXPECT_NE(error_of([&] { pass.run({lit.id(), albedo.id(), wrong.id()}); }).find("'reflection' has internal format"),
            std::string::npos);
  EXPECT_NE(error_of([&] { pass.run({lit.id(), 0, lit.id()}); }).find("'albedo_reflectivity' is texture 0"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::render
