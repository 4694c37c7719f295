#version 450 core
// Reflection composite (ResolvePass, docs/ssr.md):
//   final = srgb_encode(tone_map(exposure * (lit + reflectivity * reflection)))
// `reflection` is already faded and blurred (ReflectionBlurPass); reflectivity is the G-buffer's
// albedo alpha. The result is stored sRGB-encoded into an RGBA8 (UNORM) image, a = 1.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform readonly image2D lit;
layout(binding = 1, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 2, rgba16f) uniform readonly image2D reflection;
layout(binding = 3, rgba8) uniform writeonly image2D final_image;

uniform float exposure;
uniform int tone_map;  // ToneMap: 0 none, 1 reinhard, 2 aces

vec3 apply_tone_map(vec3 c) {
  c = max(c, vec3(0.0));
  if (tone_map == 1) return c / (1.0 + c);
  if (tone_map == 2) {
    // Narkowicz 2015, "ACES Filmic Tone Mapping Curve" (fit of the ACES RRT + ODT).
    return clamp((c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
  }
  return min(c, vec3(1.0));
}

// IEC 61966-2-1 sRGB transfer function.
vec3 srgb_encode(vec3 linear) {
  const vec3 low = linear * 12.92;
  const vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
  return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(lit)))) return;
  const vec3 base = imageLoad(lit, pixel).rgb;
  const float reflectivity = imageLoad(albedo_reflectivity, pixel).a;
  const vec3 mirrored = imageLoad(reflection, pixel).rgb;
  const vec3 radiance = exposure * (base + reflectivity * mirrored);
  imageStore(final_image, pixel, vec4(srgb_encode(apply_tone_map(radiance)), 1.0));
}
