#version 450 core
// Edge-aware spatial filter of the accumulated reflection (ReflectionDenoiser, docs/glossy.md): one
// a-trous iteration (5 x 5 B3-spline taps `step` pixels apart; the denoiser runs steps 1, 2, 4).
// The weight of tap q for pixel p is
//   h(i) h(j)                                            the B3-spline kernel
//   x exp(-|offset|^2 / (2 s^2)),  s = max_sigma x sqrt(min(roughness_p / 0.5, 1) / history length_p)
//                                                        footprint of the lobe: none for a mirror,
//                                                        shrinking as the history converges
//   x exp(-|n_p . (P_q - P_p)| / (depth_sigma x |P_p - camera|))   same plane (depth edges)
//   x max(n_p . n_q, 0)^normal_power                     same orientation (normal edges)
//   x exp(-|roughness_p - roughness_q| / roughness_sigma) same lobe width
// over reflective taps only, normalised (a constant stays constant). a (history length) passes through;
// non-reflective pixels are 0 (written by the last iteration only).
// Taps 3 s or more away weigh less than exp(-4.5) (1.1 %) of the centre's Gaussian factor and are
// not fetched: a converged rough pixel (s ~ 0.6) reads its 3 x 3 taps only, and an iteration whose
// step is >= 3 s passes the pixel through.
// The taps' position, normal, roughness and reflective flag come from the guide the temporal pass
// wrote (include/denoiser_guide.glsl: one fetch a tap); the centre's normal and roughness are the
// G-buffer's own.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/glossy_sampling.glsl"
#include "include/denoiser_guide.glsl"

layout(binding = 0) uniform sampler2D source;
layout(binding = 1) uniform usampler2D guide;
layout(binding = 2) uniform sampler2D world_normal_roughness;
layout(binding = 0, rgba16f) uniform writeonly image2D filtered;

uniform GuideRays rays;  // this frame's (the guide's positions)
uniform int step;
uniform int last_iteration;  // 1 in the denoiser's last iteration, whose output is every pixel's
uniform float max_sigma;
uniform float depth_sigma;
uniform float normal_power;
uniform float roughness_sigma;

const float kB3[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const float kLog2e = 1.4426950408889634;

void main() {
  const ivec2 size = textureSize(source, 0);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const uvec2 own = texelFetch(guide, pixel, 0).xy;
  if (!guide_reflective(own)) {
    // No tap reads a non-reflective pixel: only the last iteration stores its output, 0.
    if (last_iteration != 0) imageStore(filtered, pixel, vec4(0.0));
    return;
  }
  const vec4 centre = texelFetch(source, pixel, 0);
  const vec4 normal_roughness = texelFetch(world_normal_roughness, pixel, 0);
  const float roughness = glossy_roughness(normal_roughness.w);
  const float sigma = max_sigma * sqrt(min(roughness / 0.5, 1.0)) / sqrt(max(centre.a, 1.0));
  if (sigma <= 0.0 || float(step) >= 3.0 * sigma) {
    imageStore(filtered, pixel, centre);
    return;
  }
  const vec3 position = guide_position(rays, pixel, own);
  const vec3 normal = normalize(normal_roughness.xyz);
  const float roughness_key = guide_roughness(own);  // quantised like the taps': equal for one material
  const float reach = 9.0 * sigma * sigma;          // (3 s)^2
  const float plane_scale = 1.0 / (depth_sigma * max(distance(camera_position.xyz, position), 1e-6));
  const float inverse_two_sigma2 = 1.0 / (2.0 * sigma * sigma);
  const float inverse_roughness_sigma = 1.0 / roughness_sigma;
  vec3 sum = vec3(0.0);
  float weight_sum = 0.0;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i) {
      const ivec2 offset = ivec2(i, j) * step;
      const float d2 = float(offset.x * offset.x + offset.y * offset.y);
      if (d2 >= reach) continue;
      const ivec2 q = pixel + offset;
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      const uvec2 tap = texelFetch(guide, q, 0).xy;
      if (!guide_reflective(tap)) continue;
      const float plane = abs(dot(normal, guide_position(rays, q, tap) - position)) * plane_scale;
      // The Gaussian, plane, normal and roughness factors in one exp2: exp(a) exp(b) exp(c) x^p =
      // 2^(log2(e) (a + b + c) + p log2(x)); a normal facing away (x <= 0) gives 2^(p log2(1e-30)),
      // 0 for p >= 1 as max(x, 0)^p.
      const float exponent =
          -d2 * inverse_two_sigma2 - plane - abs(roughness_key - guide_roughness(tap)) * inverse_roughness_sigma;
      const float w = kB3[abs(i)] * kB3[abs(j)] *
                      exp2(kLog2e * exponent + normal_power * log2(max(dot(normal, guide_normal(tap)), 1e-30)));
      sum += w * texelFetch(source, q, 0).rgb;
      weight_sum += w;
    }
  imageStore(filtered, pixel, vec4(weight_sum > 0.0 ? sum / weight_sum : centre.rgb, centre.a));
}
