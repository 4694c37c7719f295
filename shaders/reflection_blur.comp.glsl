#version 450 core
// Reflection fade + separable Gaussian blur (ReflectionBlurPass, docs/ssr.md). Three modes:
//   0 fade only (radius 0): target = vec4(rgb * fade(a), a), bit-exact when the fade is off;
//   1 horizontal: target.rgb = sum w_i v_i fade(a_i) rgb_i / sum w_i v_i, target.a = coverage =
//     sum w_i v_i / sum w_i, where v_i = 1 if sample i found a reflection (a > 0) and is on screen;
//   2 vertical: the same over the horizontal result with v_j = coverage_j, which makes the two
//     passes together the exact 2D normalised convolution. Pixels whose own original a is 0 get 0
//     (no reflection bleeds into them); the output keeps the original distance in a.
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform readonly image2D source;
layout(binding = 1, rgba16f) uniform writeonly image2D target;
layout(binding = 2, rgba16f) uniform readonly image2D original;

uniform int mode;
uniform int radius;
uniform float sigma;
uniform float fade_start;
uniform float fade_end;

float fade(float distance) {
  if (fade_end <= 0.0) return 1.0;
  return 1.0 - smoothstep(fade_start, fade_end, distance);
}

void main() {
  const ivec2 size = imageSize(source);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;

  if (mode == 0) {
    const vec4 c = imageLoad(source, pixel);
    imageStore(target, pixel, vec4(c.rgb * fade(c.a), c.a));
    return;
  }

  const ivec2 axis = mode == 1 ? ivec2(1, 0) : ivec2(0, 1);
  const float inv_two_sigma2 = 1.0 / (2.0 * sigma * sigma);
  vec3 sum = vec3(0.0);
  float weight_sum = 0.0;
  float kernel_sum = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    const float w = exp(-float(i * i) * inv_two_sigma2);
    kernel_sum += w;
    const ivec2 q = pixel + axis * i;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    const vec4 c = imageLoad(source, q);
    if (mode == 1) {
      if (c.a <= 0.0) continue;
      sum += w * fade(c.a) * c.rgb;
      weight_sum += w;
    } else {
      sum += (w * c.a) * c.rgb;
      weight_sum += w * c.a;
    }
  }
  const vec3 mean = weight_sum > 0.0 ? sum / weight_sum : vec3(0.0);
  if (mode == 1) {
    imageStore(target, pixel, vec4(mean, weight_sum / kernel_sum));
  } else {
    const float distance = imageLoad(original, pixel).a;
    imageStore(target, pixel, distance > 0.0 ? vec4(mean, distance) : vec4(0.0));
  }
}
