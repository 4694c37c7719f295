#include "render/tone_map.h"

namespace glint::render {
namespace shader {

// shaders/include/tone_map.glsl is written in the subset of GLSL that glm also speaks; its calls
// (max, clamp, pow, mix, lessThanEqual) find glm's functions through their glm arguments.
using glm::vec3;
#include "../../shaders/include/tone_map.glsl"

}  // namespace shader

vec3 tone_mapped_srgb(const vec3& linear, ToneMap tone_map) {
  return shader::srgb_encode(shader::apply_tone_map(linear, static_cast<int>(tone_map)));
}

ImageRgba8 tone_map_to_rgba8(const ImageRgbaF& linear, ToneMap tone_map) {
  ImageRgbaF encoded(linear.width, linear.height);
  for (std::size_t i = 0; i < linear.pixels.size(); ++i)
    encoded.pixels[i] = vec4(tone_mapped_srgb(vec3(linear.pixels[i]), tone_map), 1.0f);
  return quantize_to_rgba8(encoded);
}

}  // namespace glint::render
