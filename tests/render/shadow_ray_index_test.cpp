// The dense shadow-ray list's order (shaders/include/shadow_ray_index.glsl through its C++ build):
// every pixel of an image of any size has its own index below width * height, and a whole 8 x 4
// block of pixels is 32 consecutive rays (one warp), which is why the order exists.
#include "render/shadow_ray_index.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace glint::render {
namespace {

TEST(ShadowRayIndex, EveryPixelOfAnySizeHasItsOwnIndexInTheList) {
  const int sizes[][2] = {{1, 1}, {1, 17}, {64, 1}, {7, 3}, {8, 4}, {9, 5}, {37, 23}, {157, 91}, {1280, 720}};
  for (const auto& size : sizes) {
    const int width = size[0], height = size[1];
    SCOPED_TRACE(testing::Message() << width << "x" << height);
    std::vector<int> seen(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t index = shadow_ray_index(x, y, width, height);
        ASSERT_LT(index, seen.size()) << "pixel " << x << "," << y;
        ++seen[index];
      }
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "index " << i;
  }
}

TEST(ShadowRayIndex, AWholeBlockOfEightByFourPixelsIsThirtyTwoConsecutiveRays) {
  const int width = 37, height = 23;  // full blocks at (8..15, 4..7); a partial one at the corner
  for (int y = 4; y < 8; ++y)
    for (int x = 8; x < 16; ++x)
      EXPECT_EQ(shadow_ray_index(x, y, width, height),
                shadow_ray_index(8, 4, width, height) + static_cast<std::size_t>((y - 4) * 8 + (x - 8)));
  // With a width a multiple of 8 every whole block starts at a multiple of 32: one warp's rays.
  for (int y = 0; y + 4 <= 23; y += 4)
    for (int x = 0; x < 40; x += 8) EXPECT_EQ(shadow_ray_index(x, y, 40, 23) % 32, 0u) << x << "," << y;
  // Row 0 starts the list; the last pixel of the image ends it.
  EXPECT_EQ(shadow_ray_index(0, 0, width, height), 0u);
  EXPECT_EQ(shadow_ray_index(width - 1, height - 1, width, height), static_cast<std::size_t>(width * height - 1));
}

}  // namespace
}  // namespace glint::render
