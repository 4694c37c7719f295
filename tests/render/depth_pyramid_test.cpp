// DepthPyramidPass: every level is exactly the rule of docs/ssr.md "Depth pyramid" applied to the
// level below (min of the minima, max of the maxima of the 2x2 finer texels, the last texel of a row
// or column also taking the finer level's last where that is odd), on any size, and level 0 at each
// pixel's own place.
#include "render/depth_pyramid_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_test_context.h"
#include "render/synthetic_gbuffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace glint::render {
namespace {

using testing::CpuGBuffer;
using testing::SyntheticCamera;

struct Level {
  int width = 0;
  int height = 0;
  std::vector<glm::vec2> texels;  // rows bottom first
  glm::vec2 at(int x, int y) const { return texels[static_cast<std::size_t>(y * width + x)]; }
};

Level read_level(const DepthPyramidPass& pyramid, int level) {
  Level l;
  l.width = std::max(1, pyramid.width() >> level);
  l.height = std::max(1, pyramid.height() >> level);
  l.texels.resize(static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(pyramid.texture(), level, GL_RG, GL_FLOAT,
                    static_cast<GLsizei>(l.texels.size() * sizeof(glm::vec2)), l.texels.data());
  check_gl("depth pyramid test readback");
  return l;
}

// The rule, one level from the one below it, written out plainly.
Level reference_level(const Level& finer) {
  Level l;
  l.width = std::max(1, finer.width / 2);
  l.height = std::max(1, finer.height / 2);
  l.texels.resize(static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height));
  for (int y = 0; y < l.height; ++y) {
    for (int x = 0; x < l.width; ++x) {
      const int last_x = x == l.width - 1 ? finer.width - 1 : std::min(2 * x + 1, finer.width - 1);
      const int last_y = y == l.height - 1 ? finer.height - 1 : std::min(2 * y + 1, finer.height - 1);
      glm::vec2 range(3.4e38f, -3.4e38f);
      for (int fy = 2 * y; fy <= last_y; ++fy) {
        for (int fx = 2 * x; fx <= last_x; ++fx) {
          const glm::vec2 v = finer.at(fx, fy);
          range = glm::vec2(std::min(range.x, v.x), std::max(range.y, v.y));
        }
      }
      l.texels[static_cast<std::size_t>(y * l.width + x)] = range;
    }
  }
  return l;
}

// A G-buffer of random surfaces: per pixel a point on its primary ray at a random distance from
// 0.01 to 10,000 (log-uniform), a random normal facing the camera; background pixels (w = 0) one
// in five, and whole random rectangles of background, so that coarse texels are background too.
CpuGBuffer random_gbuffer(const FrameConstants& constants, int width, int height, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  CpuGBuffer g;
  g.width = width;
  g.height = height;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  g.albedo_reflectivity.assign(n, glm::u8vec4(128, 128, 128, 0));
  g.world_position.assign(n, vec4(0.0f));
  g.world_normal.assign(n, vec4(0.0f, 1.0f, 0.0f, 0.5f));
  g.lit.assign(n, vec4(0.0f));
  g.quad.assign(n, -1);
  g.t.assign(n, 0.0f);
  const vec3 eye(constants.camera_position);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (unit(rng) < 0.2f) continue;
      const std::size_t i = g.index(x, y);
      const vec3 ray = testing::primary_ray(constants, x, y);
      const float t = 0.01f * std::pow(1e6f, unit(rng));
      vec3 normal = glm::normalize(vec3(unit(rng), unit(rng), unit(rng)) * 2.0f - 1.0f + vec3(1e-3f));
      if (glm::dot(normal, ray) > 0.0f) normal = -normal;
      g.world_position[i] = vec4(eye + ray * t, 1.0f);
      g.world_normal[i] = vec4(normal, 0.5f);
      g.quad[i] = 0;
      g.t[i] = t;
    }
  }
  for (int r = 0; r < 4; ++r) {
    const int x0 = static_cast<int>(unit(rng) * static_cast<float>(width));
    const int y0 = static_cast<int>(unit(rng) * static_cast<float>(height));
    const int x1 = std::min(width, x0 + 1 + static_cast<int>(unit(rng) * static_cast<float>(width) * 0.5f));
    const int y1 = std::min(height, y0 + 1 + static_cast<int>(unit(rng) * static_cast<float>(height) * 0.5f));
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) g.world_position[g.index(x, y)].w = 0.0f;
    }
  }
  return g;
}

using DepthPyramidTest = glint::testing::GlTest;

TEST_F(DepthPyramidTest, EveryLevelIsExactlyTheRuleAppliedToTheLevelBelowOnAnySize) {
  struct Size {
    int width, height;
  };
  // Odd sizes, 1 texel wide in one dimension from the start or from some level on, remainders of
  // the 32-pixel tiles (level 5 texels of the first dispatch) from 1 to 31 pixels, on both edges at
  // once (100x37, 1279x719, 63x65: the last tile of a row and column up to 63 pixels), fewer levels
  // than the tiles have (1x1 to 31x257), and the frame sizes; 8195x3 has 14 levels, which take two
  // tail dispatches.
  const Size sizes[] = {{37, 23},  {1, 1},   {1, 17},   {64, 1},  {257, 130}, {1280, 720}, {1279, 719},
                        {2, 1},    {1, 3},   {3, 3},    {7, 5},   {33, 2},    {33, 17},    {5, 70},
                        {63, 65},  {95, 31}, {100, 37}, {1025, 34}, {31, 257}, {127, 1},   {2049, 3},
                        {8195, 3}};
  std::uint32_t seed = 1;
  for (const Size size : sizes) {
    SCOPED_TRACE(::testing::Message() << size.width << "x" << size.height);
    SyntheticCamera camera;
    const FrameConstants constants = testing::frame_constants_for(camera, size.width, size.height);
    const CpuGBuffer cpu = random_gbuffer(constants, size.width, size.height, seed++);
    const testing::GpuGBuffer gpu = testing::upload(cpu, constants);
    DepthPyramidPass pyramid(size.width, size.height);
    ASSERT_EQ(pyramid.levels(), DepthPyramidPass::level_count(size.width, size.height));
    pyramid.run({gpu.world_position.id(), gpu.world_normal.id(), gpu.frame_constants.id()});

    // Level 0: the background value where there is no surface; elsewhere a range around the
    // pixel's own centre depth d within [d / 2, 2 d] (depths are random, so a value written to
    // another pixel's place, or not written, shows).
    Level finer = read_level(pyramid, 0);
    int background = 0;
    for (int y = 0; y < size.height; ++y) {
      for (int x = 0; x < size.width; ++x) {
        const std::size_t i = cpu.index(x, y);
        const glm::vec2 v = finer.at(x, y);
        if (cpu.world_position[i].w == 0.0f) {
          ++background;
          ASSERT_EQ(v, glm::vec2(kPyramidBackgroundDepth)) << x << ", " << y;
        } else {
          // d as the shader has it up to rounding: of the depth, and of the world position's
          // float coordinates (which dominates for a point near the camera).
          const vec3 world(cpu.world_position[i]);
          const float d = -(constants.view * vec4(world, 1.0f)).z;
          const float tolerance =
              1e-4f * d + 1e-6f * (glm::length(world) + glm::length(vec3(constants.camera_position)));
          ASSERT_GT(v.x, 0.0f) << x << ", " << y;
          ASSERT_LE(v.x, d + tolerance) << x << ", " << y;
          ASSERT_GE(v.y, d - tolerance) << x << ", " << y;
          ASSERT_GE(v.x, 0.5f * (d - tolerance)) << x << ", " << y;
          ASSERT_LE(v.y, 2.0f * (d + tolerance)) << x << ", " << y;
        }
      }
    }
    if (size.width * size.height >= 100) {
      EXPECT_GT(background, 0);
      EXPECT_LT(background, size.width * size.height);
    }

    for (int level = 1; level < pyramid.levels(); ++level) {
      const Level expected = reference_level(finer);
      const Level actual = read_level(pyramid, level);
      ASSERT_EQ(actual.width, expected.width) << "level " << level;
      ASSERT_EQ(actual.height, expected.height) << "level " << level;
      int wrong = 0;
      for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
          const glm::vec2 a = actual.at(x, y), e = expected.at(x, y);
          if (a != e && ++wrong <= 5) {
            ADD_FAILURE() << "level " << level << " texel " << x << ", " << y << ": " << a.x << " " << a.y
                          << ", expected " << e.x << " " << e.y;
          }
        }
      }
      ASSERT_EQ(wrong, 0) << "level " << level;
      finer = expected;
    }
    EXPECT_EQ(finer.width * finer.height, 1);
  }
}

TEST_F(DepthPyramidTest, HasAFullMipChainOfLevels) {
  EXPECT_EQ(DepthPyramidPass(1280, 720).levels(), 11);
  EXPECT_EQ(DepthPyramidPass(2560, 1440).levels(), 12);
  EXPECT_EQ(DepthPyramidPass(1, 1).levels(), 1);
  EXPECT_EQ(DepthPyramidPass(64, 1).levels(), 7);
  EXPECT_EQ(DepthPyramidPass(32, 3).levels(), 6);
}

}  // namespace
}  // namespace glint::render
