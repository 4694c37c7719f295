#include "scene/procedural/textures.h"

#include "scene/procedural/noise.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::procedural {
namespace {

constexpr float kTwoPi = 6.28318530718f;

// Fills a size x size texture from `shade(u, v)` -> sRGB colour in 0..1, where (u, v) in [0, 1)
// are image coordinates with v growing downwards (row 0 first). Rows are independent, so they are
// shaded in parallel; the result does not depend on the scheduling.
template <typename Shade>
Texture fill_texture(const std::string& kind, int size, const Shade& shade) {
  Texture texture;
  texture.name = "procedural:" + kind;
  texture.width = size;
  texture.height = size;
  texture.rgba.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4u);
  const float inverse = 1.0f / static_cast<float>(size);
  tbb::parallel_for(0, size, [&](int row) {
    std::uint8_t* out = texture.rgba.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(size) * 4u;
    for (int column = 0; column < size; ++column) {
      const vec3 colour = glm::clamp(shade((static_cast<float>(column) + 0.5f) * inverse, (static_cast<float>(row) + 0.5f) * inverse), 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) out[column * 4 + c] = static_cast<std::uint8_t>(std::lround(colour[c] * 255.0f));
      out[column * 4 + 3] = 255;
    }
  });
  return texture;
}

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// 0 on a joint line of half-width `half_width` (in cell units), 1 inside the cell, soft edge.
float joint_mask(float fraction_x, float fraction_y, float half_width_x, float half_width_y) {
  const float dx = std::min(fraction_x, 1.0f - fraction_x), dy = std::min(fraction_y, 1.0f - fraction_y);
  return smoothstep(half_width_x, half_width_x * 2.0f, dx) * smoothstep(half_width_y, half_width_y * 2.0f, dy);
}

// Courses of blocks: returns the block's id (for its colour) and the joint mask at (u, v).
struct Masonry {
  std::uint32_t block_id;
  float joint;  // 0 on mortar, 1 on the block face
};
Masonry masonry(float u, float v, int rows, int columns, float mortar_u, float mortar_v) {
  const float y = v * static_cast<float>(rows);
  const int row = std::min(static_cast<int>(y), rows - 1);
  // Alternate courses shift by half a block (running bond); the shift wraps, so the texture tiles.
  float x = u * static_cast<float>(columns) + ((row % 2) ? 0.5f : 0.0f);
  if (x >= static_cast<float>(columns)) x -= static_cast<float>(columns);
  const int column = std::min(static_cast<int>(x), columns - 1);
  return {hash_lattice(column, row, 7u), joint_mask(x - std::floor(x), y - std::floor(y), mortar_u, mortar_v)};
}

}  // namespace

Texture make_marble_texture(int size) {
  return fill_texture("marble", size, [](float u, float v) {
    // Four tiles per texture (the floor maps one texture onto 2 m x 2 m): checker of two marbles.
    const int tile = (u >= 0.5f ? 1 : 0) + (v >= 0.5f ? 1 : 0);
    const bool light = (tile % 2) == 0;
    const float tu = std::fmod(u * 2.0f, 1.0f), tv = std::fmod(v * 2.0f, 1.0f);
    const float warp = fbm(u * 4.0f, v * 4.0f, 4, 5, light ? 11u : 12u);
    const float vein = std::abs(std::sin(kTwoPi * (u * 3.0f + v * 2.0f) + 9.0f * warp));
    const float vein_dark = 1.0f - smoothstep(0.0f, 0.12f, vein);  // thin dark veins where the sine crosses zero
    const float cloud = fbm(u * 8.0f, v * 8.0f, 8, 4, light ? 21u : 22u);
    vec3 colour = light ? vec3(0.90f, 0.88f, 0.84f) : vec3(0.55f, 0.47f, 0.45f);
    colour *= 0.9f + 0.2f * cloud;
    colour = glm::mix(colour, light ? vec3(0.55f, 0.55f, 0.58f) : vec3(0.28f, 0.22f, 0.22f), 0.7f * vein_dark);
    const float grout = joint_mask(tu, tv, 0.004f, 0.004f);
    return glm::mix(vec3(0.30f, 0.29f, 0.27f), colour, grout);
  });
}

Texture make_stone_texture(int size) {
  return fill_texture("stone", size, [](float u, float v) {
    const Masonry block = masonry(u, v, 4, 2, 0.006f, 0.012f);
    const float tint = hash_to_unit(block.block_id);
    const float grain = fbm(u * 16.0f, v * 16.0f, 16, 4, 31u);
    const float pits = value_noise(u * 128.0f, v * 128.0f, 128, 32u);
    vec3 colour = glm::mix(vec3(0.72f, 0.66f, 0.56f), vec3(0.80f, 0.75f, 0.64f), tint);
    colour *= 0.82f + 0.3f * grain - 0.08f * pits;
    return glm::mix(vec3(0.45f, 0.42f, 0.38f), colour, block.joint);
  });
}

Texture make_brick_texture(int size) {
  return fill_texture("brick", size, [](float u, float v) {
    const Masonry brick = masonry(u, v, 24, 8, 0.03f, 0.08f);
    const float tint = hash_to_unit(brick.block_id);
    const float grain = fbm(u * 32.0f, v * 32.0f, 32, 3, 41u);
    vec3 colour = glm::mix(vec3(0.55f, 0.27f, 0.18f), vec3(0.70f, 0.40f, 0.26f), tint);
    colour *= 0.85f + 0.25f * grain;
    return glm::mix(vec3(0.62f, 0.60f, 0.55f), colour, brick.joint);
  });
}

Texture make_plaster_texture(int size) {
  return fill_texture("plaster", size, [](float u, float v) {
    const float blotch = fbm(u * 4.0f, v * 4.0f, 4, 6, 51u);
    const float fine = value_noise(u * 96.0f, v * 96.0f, 96, 52u);
    return vec3(0.86f, 0.82f, 0.74f) * (0.86f + 0.2f * blotch + 0.04f * fine);
  });
}

Texture make_wood_texture(int size) {
  return fill_texture("wood", size, [](float u, float v) {
    constexpr int kPlanks = 4;
    const float y = v * kPlanks;
    const int plank = std::min(static_cast<int>(y), kPlanks - 1);
    const float across = y - std::floor(y);
    const float warp = fbm(u * 2.0f, v * 8.0f, 2, 4, 61u + static_cast<std::uint32_t>(plank));
    const float rings = 0.5f + 0.5f * std::sin(kTwoPi * (across * 6.0f + 5.0f * warp));
    const float tint = hash_to_unit(hash_lattice(plank, 0, 62u));
    vec3 colour = glm::mix(vec3(0.42f, 0.26f, 0.14f), vec3(0.58f, 0.38f, 0.21f), 0.6f * rings + 0.4f * tint);
    const float seam = smoothstep(0.0f, 0.02f, std::min(across, 1.0f - across));
    return colour * (0.55f + 0.45f * seam);
  });
}

Texture make_fabric_texture(int size, vec3 base, vec3 accent, std::uint32_t seed) {
  return fill_texture("fabric", size, [base, accent, seed](float u, float v) {
    // Fine weave: warp and weft threads as a product of two high-frequency sines.
    const float weave = 0.5f + 0.5f * std::sin(kTwoPi * u * 160.0f) * std::sin(kTwoPi * v * 160.0f);
    const float dye = fbm(u * 6.0f, v * 6.0f, 6, 4, seed);
    vec3 colour = base * (0.8f + 0.2f * dye) * (0.9f + 0.1f * weave);
    // Border stripes and a diamond emblem in the accent colour.
    const float edge = std::min(std::min(u, 1.0f - u), std::min(v, 1.0f - v));
    const bool border = (edge > 0.03f && edge < 0.06f) || (edge > 0.08f && edge < 0.09f);
    const float diamond = std::abs(u - 0.5f) * 1.6f + std::abs(v - 0.4f);
    const bool emblem = diamond < 0.18f && diamond > 0.14f ? true : diamond < 0.08f;
    if (border || emblem) colour = accent * (0.85f + 0.15f * weave);
    return colour;
  });
}

}  // namespace glint::procedural
