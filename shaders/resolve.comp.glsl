#version 450 core
// Reflection composite (ResolvePass, docs/ssr.md):
//   final = srgb_encode(tone_map(exposure * (lit + reflectivity * reflection)))
// `reflection` is already faded and blurred (ReflectionBlurPass); reflectivity is the G-buffer's
// albedo alpha. The result is stored sRGB-encoded into an RGBA8 (UNORM) image, a = 1; with
// store_linear (`glint render --format exr`) the tone map's input goes to linear_image as well.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform readonly image2D lit;
layout(binding = 1, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 2, rgba16f) uniform readonly image2D reflection;
layout(binding = 3, rgba8) uniform writeonly image2D final_image;
layout(binding = 4, rgba32f) uniform writeonly image2D linear_image;  // bound only with store_linear

uniform float exposure;
uniform int tone_map;  // ToneMap: 0 none, 1 reinhard, 2 aces
uniform int store_linear;  // 1: also write linear_image

#include "include/tone_map.glsl"

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(lit)))) return;
  const vec3 base = imageLoad(lit, pixel).rgb;
  const float reflectivity = imageLoad(albedo_reflectivity, pixel).a;
  const vec3 mirrored = imageLoad(reflection, pixel).rgb;
  const vec3 radiance = exposure * (base + reflectivity * mirrored);
  imageStore(final_image, pixel, vec4(srgb_encode(apply_tone_map(radiance, tone_map)), 1.0));
  if (store_linear != 0) imageStore(linear_image, pixel, vec4(radiance, 1.0));
}
