// Glossy reflection directions (docs/glossy.md): GGX importance sampling of the visible normals
// (Heitz, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4), 2018) driven by a
// low-discrepancy sequence. Twin of src/render/glossy_sampling.h: the two must compute the same
// numbers (tests/render/glossy_sampling_gl_test.cpp compares them).
//
//   incident   unit direction from the eye (camera) to the surface point
//   normal     the surface normal, either orientation (it is turned towards the eye here)
//   roughness  the material's roughness; alpha = roughness^2 (the convention of scene/specular_roughness.h)
//   u          a point of [0, 1)^2
// Roughness 0 returns normalize(reflect(incident, normal)), the mirror direction, bit for bit as the
// passes computed it before glossy reflections, and a weight of exactly 1.
//
// The sequence: sample n (n = frame * samples_per_pixel + sample) of a pixel is the R2 sequence
// (Roberts 2018, the plastic number) in 32-bit fixed point, n * (A1, A2), shifted per pixel: the
// first coordinate by the R2 dither mask of the pixel (px * A1 + py * A2, a blue-noise-like pattern
// over the screen), the second by a hash of the pixel. Integer arithmetic, so the GLSL and C++ points
// are identical.
#include "include/frame_constants.glsl"

const float kGlossyPi = 3.14159265358979;
const uint kR2A1 = 3242174889u;  // round(2^32 / plastic number)
const uint kR2A2 = 2447445413u;  // round(2^32 / plastic number^2)

uint glossy_hash(uint x) {  // PCG output permutation of a linear congruential step
  uint state = x * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

vec2 glossy_sample_point(uvec2 pixel, uint index) {
  const uint first = index * kR2A1 + pixel.x * kR2A1 + pixel.y * kR2A2;
  const uint second = index * kR2A2 + glossy_hash(pixel.x + 65536u * pixel.y);
  return vec2(float(first >> 8u), float(second >> 8u)) * (1.0 / 16777216.0);
}

// Tangent and bitangent of a unit normal (Duff et al., "Building an Orthonormal Basis, Revisited",
// JCGT 6(1), 2017).
void glossy_basis(vec3 n, out vec3 t, out vec3 b) {
  const float s = n.z >= 0.0 ? 1.0 : -1.0;
  const float a = -1.0 / (s + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// A GGX normal (z up, alpha isotropic) seen from wo_local, distributed as the visible normals.
vec3 ggx_visible_normal(vec3 wo_local, float alpha, vec2 u) {
  const vec3 vh = normalize(vec3(alpha * wo_local.x, alpha * wo_local.y, wo_local.z));  // the hemisphere's frame
  const float length_sq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = length_sq > 0.0 ? vec3(-vh.y, vh.x, 0.0) / sqrt(length_sq) : vec3(1.0, 0.0, 0.0);
  const vec3 t2 = cross(vh, t1);
  const float r = sqrt(u.x);
  const float phi = 2.0 * kGlossyPi * u.y;
  const float p1 = r * cos(phi);
  const float s = 0.5 * (1.0 + vh.z);
  const float p2 = mix(sqrt(max(1.0 - p1 * p1, 0.0)), r * sin(phi), s);  // the visible part of the disk
  const vec3 nh = p1 * t1 + p2 * t2 + sqrt(max(1.0 - p1 * p1 - p2 * p2, 0.0)) * vh;
  return normalize(vec3(alpha * nh.x, alpha * nh.y, max(nh.z, 0.0)));  // back to the ellipsoid
}

vec3 reflection_direction(vec3 incident, vec3 normal, float roughness, vec2 u) {
  if (roughness <= 0.0) return normalize(reflect(incident, normal));
  const vec3 n = dot(normal, incident) > 0.0 ? -normal : normal;
  vec3 t, b;
  glossy_basis(n, t, b);
  const vec3 wo = -incident;
  const vec3 h_local = ggx_visible_normal(vec3(dot(wo, t), dot(wo, b), dot(wo, n)), roughness * roughness, u);
  const vec3 h = h_local.x * t + h_local.y * b + h_local.z * n;
  return normalize(reflect(incident, h));
}

// Smith's Lambda for GGX at cos(theta) = c > 0.
float ggx_lambda(float c, float alpha) {
  const float tan_sq = max(1.0 - c * c, 0.0) / (c * c);
  return 0.5 * (sqrt(1.0 + alpha * alpha * tan_sq) - 1.0);
}

// The estimator's weight of a direction drawn by reflection_direction: BRDF x cosine / pdf without
// the Fresnel term (the reflectivity is glint's Fresnel), G2(v, l) / G1(v) with the height-correlated
// Smith G2; 0 for a direction below the surface.
float reflection_weight(vec3 incident, vec3 normal, float roughness, vec3 direction) {
  if (roughness <= 0.0) return 1.0;
  const vec3 n = dot(normal, incident) > 0.0 ? -normal : normal;
  const float n_v = dot(n, -incident), n_l = dot(n, direction);
  if (n_l <= 0.0 || n_v <= 0.0) return 0.0;
  const float alpha = roughness * roughness;
  const float lambda_v = ggx_lambda(n_v, alpha);
  return (1.0 + lambda_v) / (1.0 + lambda_v + ggx_lambda(n_l, alpha));
}

// ---- the frame's sampling (FrameConstants::reflection_sampling) ----

// The roughness the reflection passes use: the material's, or 0 when glossy reflections are off.
float glossy_roughness(float material_roughness) { return reflection_sampling.w != 0.0 ? material_roughness : 0.0; }

// True above the roughness cutoff: SSR leaves such pixels to the rays.
bool beyond_ssr_roughness(float material_roughness) {
  return glossy_roughness(material_roughness) > reflection_sampling.x;
}

// This frame's sample of `pixel`: sample reflection_sampling.y of reflection_sampling.z per frame.
vec2 pixel_sample_point(ivec2 pixel) {
  const uint index = uint(viewport.z) * uint(reflection_sampling.z) + uint(reflection_sampling.y);
  return glossy_sample_point(uvec2(pixel), index);
}

vec3 pixel_reflection_direction(vec3 incident, vec3 normal, float material_roughness, ivec2 pixel) {
  return reflection_direction(incident, normal, glossy_roughness(material_roughness), pixel_sample_point(pixel));
}
