#version 450 core
// Reflection samples of one frame averaged (ReflectionAccumulation, docs/glossy.md): with --spp N
// the reflection passes run N times per frame; after each, this adds the reflection image into a
// sum (rgb, distance, hits), and after the last writes the mean back into the reflection image:
//   rgb = sum of rgb / N (a sample without a reflection counts as black),
//   a   = mean distance over the samples that found a reflection (0: none did).
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform image2D reflection;
layout(binding = 1, rgba32f) uniform image2D sum;   // rgb, distance
layout(binding = 2, r32f) uniform image2D hits;

uniform int sample_index;
uniform int samples;

void main() {
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(reflection)))) return;
  const vec4 value = imageLoad(reflection, pixel);
  const float hit = value.a > 0.0 ? 1.0 : 0.0;
  vec4 total = vec4(value.rgb, hit * value.a);
  float hit_count = hit;
  if (sample_index > 0) {
    total += imageLoad(sum, pixel);
    hit_count += imageLoad(hits, pixel).r;
  }
  if (sample_index + 1 < samples) {
    imageStore(sum, pixel, total);
    imageStore(hits, pixel, vec4(hit_count));
    return;
  }
  imageStore(reflection, pixel, vec4(total.rgb / float(samples), hit_count > 0.0 ? total.a / hit_count : 0.0));
}
