#include "render/debug_views.h"

#include <algorithm>

namespace glint::render {
namespace {

// Applies `colour_of` to every pixel and quantises; alpha is always opaque.
template <typename ColourOf>
ImageRgba8 map_pixels(const ImageRgbaF& image, ColourOf&& colour_of) {
  ImageRgbaF mapped(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) mapped.pixels[i] = vec4(colour_of(image.pixels[i]), 1.0f);
  return quantize_to_rgba8(mapped);
}

bool is_background(const vec4& world_position) { return world_position.w == 0.0f; }

}  // namespace

ImageRgba8 albedo_view(const ImageRgbaF& albedo_reflectivity) {
  return map_pixels(albedo_reflectivity, [](const vec4& p) { return vec3(p); });
}

ImageRgba8 normal_view(const ImageRgbaF& world_normal) {
  return map_pixels(world_normal, [](const vec4& p) {
    const vec3 n(p);
    return glm::dot(n, n) == 0.0f ? vec3(0.0f) : 0.5f * n + 0.5f;
  });
}

ImageRgba8 position_view(const ImageRgbaF& world_position, const Aabb& world_bounds) {
  const vec3 size = glm::max(world_bounds.extent(), vec3(1e-6f));
  return map_pixels(world_position, [&](const vec4& p) {
    return is_background(p) ? vec3(0.0f) : (vec3(p) - world_bounds.min) / size;
  });
}

ImageRgba8 depth_view(const ImageRgbaF& world_position, const FrameConstants& frame) {
  const ImageRgbaF depth = view_depth(world_position, frame);
  float farthest = 0.0f;
  for (const vec4& p : depth.pixels) farthest = std::max(farthest, p.x);
  return map_pixels(depth, [&](const vec4& p) {
    if (p.x <= 0.0f || farthest <= 0.0f) return vec3(0.0f);  // background, or nothing in front
    return vec3(std::clamp(1.0f - p.x / farthest, 0.0f, 1.0f));
  });
}

ImageRgbaF opaque(ImageRgbaF image) {
  for (vec4& p : image.pixels) p.w = 1.0f;
  return image;
}

ImageRgbaF view_depth(const ImageRgbaF& world_position, const FrameConstants& frame) {
  ImageRgbaF depth(world_position.width, world_position.height, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  for (std::size_t i = 0; i < depth.pixels.size(); ++i) {
    const vec4& p = world_position.pixels[i];
    // The camera looks down -z in view space, so depth is -z; camera-relative, as the shaders'
    // view_from_world (exact far from the origin, docs/render.md).
    const vec3 relative = vec3(p) - vec3(frame.camera_position);
    if (!is_background(p)) depth.pixels[i] = vec4(vec3(-(glm::mat3(frame.view) * relative).z), 1.0f);
  }
  return depth;
}

ImageRgbaF red_as_grey(const ImageRgbaF& image) {
  ImageRgbaF grey(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) grey.pixels[i] = vec4(vec3(image.pixels[i].x), 1.0f);
  return grey;
}

ImageRgbaF unit_colours(const ImageRgba8& image) {
  ImageRgbaF colours(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) colours.pixels[i] = vec4(image.pixels[i]) / 255.0f;
  return colours;
}

ImageRgba8 grey_view(const ImageRgbaF& image) {
  return map_pixels(image, [](const vec4& p) { return vec3(std::clamp(p.x, 0.0f, 1.0f)); });
}

ImageRgba8 reflection_view(const ImageRgbaF& reflection) {
  return map_pixels(reflection, [](const vec4& p) {
    const vec3 c = glm::max(vec3(p), vec3(0.0f));
    return c / (vec3(1.0f) + c);
  });
}

ImageRgba8 tile_class_view(std::span<const TileClass> classes, int tile_columns, int width, int height) {
  static constexpr glm::u8vec4 kColours[kTileClassCount] = {
      {0, 0, 0, 255}, {40, 170, 60, 255}, {230, 200, 40, 255}, {220, 50, 40, 255}};
  ImageRgba8 image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int gl_y = height - 1 - y;  // the tiles' rows count from the bottom, as GL's
      const auto tile = static_cast<std::size_t>((gl_y / 8) * tile_columns + x / 8);
      glm::u8vec4 colour = tile < classes.size() ? kColours[static_cast<std::size_t>(classes[tile]) % kTileClassCount]
                                                 : kColours[0];
      if (x % 8 == 0 || gl_y % 8 == 0) colour = glm::u8vec4(glm::uvec4(colour) * 3u / 4u);
      image.at(x, y) = colour;
    }
  return image;
}

void mark_traced_tiles(ImageRgbaF& failure_mask, std::span<const TileClass> classes, int tile_columns) {
  for (int y = 0; y < failure_mask.height; ++y)
    for (int x = 0; x < failure_mask.width; ++x) {
      const int gl_y = failure_mask.height - 1 - y;
      const auto tile = static_cast<std::size_t>((gl_y / 8) * tile_columns + x / 8);
      if (tile >= classes.size()) continue;
      if (classes[tile] == TileClass::rt_only) failure_mask.at(x, y).x = 1.0f;
      if (classes[tile] == TileClass::none) failure_mask.at(x, y).x = 0.0f;
    }
}

}  // namespace glint::render
