#pragma once
// Deterministic test images for the metric tests: seeded random pixels, so every run sees the same
// values and a failure can be reproduced.
#include "core/image.h"
#include "metrics/channel_planes.h"

#include <random>

namespace glint::testing {

// Every channel uniform in [low, high]; alpha 255.
inline ImageRgba8 random_rgba8(int width, int height, unsigned seed, int low = 0, int high = 255) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> value(low, high);
  ImageRgba8 image(width, height);
  for (glm::u8vec4& p : image.pixels)
    p = glm::u8vec4(static_cast<std::uint8_t>(value(rng)), static_cast<std::uint8_t>(value(rng)),
                    static_cast<std::uint8_t>(value(rng)), 255);
  return image;
}

// Uniform in [low, high) (not quantised, as SSIM's planes may be).
inline metrics::Plane random_plane(int width, int height, unsigned seed, double low, double high) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(low, high);
  metrics::Plane plane(width, height);
  for (double& v : plane.pixels) v = value(rng);
  return plane;
}

inline ImageRgba8 uniform_rgba8(int width, int height, glm::u8vec4 colour) { return ImageRgba8(width, height, colour); }

}  // namespace glint::testing
