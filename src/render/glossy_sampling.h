#pragma once
// Glossy reflection directions on the CPU: the twin of shaders/include/glossy_sampling.glsl (GGX
// visible-normal sampling, Heitz 2018, driven by an R2 low-discrepancy sequence; docs/glossy.md),
// function for function, for the tests (the sampler against its pdf) and for anyone who needs the
// passes' directions on the host. Keep the two equal: tests/render/glossy_sampling_gl_test.cpp runs
// the GLSL and compares.
#include "core/math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace glint::render::glossy {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr std::uint32_t kR2A1 = 3242174889u;  // round(2^32 / plastic number)
inline constexpr std::uint32_t kR2A2 = 2447445413u;  // round(2^32 / plastic number^2)

inline std::uint32_t hash(std::uint32_t x) {
  const std::uint32_t state = x * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Point `index` of `pixel`'s sequence in [0, 1)^2 (exactly the GLSL's: integer arithmetic).
inline vec2 sample_point(glm::uvec2 pixel, std::uint32_t index) {
  const std::uint32_t first = index * kR2A1 + pixel.x * kR2A1 + pixel.y * kR2A2;
  const std::uint32_t second = index * kR2A2 + hash(pixel.x + 65536u * pixel.y);
  return vec2(static_cast<float>(first >> 8u), static_cast<float>(second >> 8u)) * (1.0f / 16777216.0f);
}

inline void basis(const vec3& n, vec3& t, vec3& b) {
  const float s = n.z >= 0.0f ? 1.0f : -1.0f;
  const float a = -1.0f / (s + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

inline vec3 ggx_visible_normal(const vec3& wo_local, float alpha, vec2 u) {
  const vec3 vh = glm::normalize(vec3(alpha * wo_local.x, alpha * wo_local.y, wo_local.z));
  const float length_sq = vh.x * vh.x + vh.y * vh.y;
  const vec3 t1 = length_sq > 0.0f ? vec3(-vh.y, vh.x, 0.0f) / std::sqrt(length_sq) : vec3(1.0f, 0.0f, 0.0f);
  const vec3 t2 = glm::cross(vh, t1);
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  const float p1 = r * std::cos(phi);
  const float s = 0.5f * (1.0f + vh.z);
  const float p2 = glm::mix(std::sqrt(std::max(1.0f - p1 * p1, 0.0f)), r * std::sin(phi), s);
  const vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(1.0f - p1 * p1 - p2 * p2, 0.0f)) * vh;
  return glm::normalize(vec3(alpha * nh.x, alpha * nh.y, std::max(nh.z, 0.0f)));
}

// The normal turned towards the eye.
inline vec3 facing_normal(const vec3& incident, const vec3& normal) {
  return glm::dot(normal, incident) > 0.0f ? -normal : normal;
}

inline vec3 reflection_direction(const vec3& incident, const vec3& normal, float roughness, vec2 u) {
  if (roughness <= 0.0f) return glm::normalize(glm::reflect(incident, normal));
  const vec3 n = facing_normal(incident, normal);
  vec3 t, b;
  basis(n, t, b);
  const vec3 wo = -incident;
  const vec3 h_local = ggx_visible_normal(vec3(glm::dot(wo, t), glm::dot(wo, b), glm::dot(wo, n)), roughness * roughness, u);
  const vec3 h = h_local.x * t + h_local.y * b + h_local.z * n;
  return glm::normalize(glm::reflect(incident, h));
}

inline float ggx_lambda(float c, float alpha) {
  const float tan_sq = std::max(1.0f - c * c, 0.0f) / (c * c);
  return 0.5f * (std::sqrt(1.0f + alpha * alpha * tan_sq) - 1.0f);
}

inline float reflection_weight(const vec3& incident, const vec3& normal, float roughness, const vec3& direction) {
  if (roughness <= 0.0f) return 1.0f;
  const vec3 n = facing_normal(incident, normal);
  const float n_v = glm::dot(n, -incident), n_l = glm::dot(n, direction);
  if (n_l <= 0.0f || n_v <= 0.0f) return 0.0f;
  const float alpha = roughness * roughness;
  const float lambda_v = ggx_lambda(n_v, alpha);
  return (1.0f + lambda_v) / (1.0f + lambda_v + ggx_lambda(n_l, alpha));
}

// ---- for the tests: the density the sampler draws from (not in the GLSL) ----

// GGX normal distribution D(h) at cos(theta_h) = c.
inline double ggx_d(double c, double alpha) {
  if (c <= 0.0) return 0.0;
  const double a2 = alpha * alpha;
  const double k = c * c * (a2 - 1.0) + 1.0;
  return a2 / (3.14159265358979323846 * k * k);
}

// The solid-angle density of reflection_direction's output l for a roughness > 0:
// pdf(l) = D_v(h) / (4 v.h) = G1(v) D(h) / (4 n.v), h = normalize(v + l), for v.h > 0.
inline double reflection_pdf(const glm::dvec3& incident, const glm::dvec3& normal, double roughness,
                             const glm::dvec3& direction) {
  const glm::dvec3 v = -incident;
  const glm::dvec3 n = glm::dot(normal, v) < 0.0 ? -normal : normal;
  const glm::dvec3 sum = v + direction;
  if (glm::dot(sum, sum) <= 0.0) return 0.0;
  const glm::dvec3 h = glm::normalize(sum);
  if (glm::dot(v, h) <= 0.0) return 0.0;
  const double alpha = roughness * roughness;
  const double n_v = glm::dot(n, v);
  const double tan_sq = std::max(1.0 - n_v * n_v, 0.0) / (n_v * n_v);
  const double g1 = 1.0 / (1.0 + 0.5 * (std::sqrt(1.0 + alpha * alpha * tan_sq) - 1.0));
  return g1 * ggx_d(glm::dot(n, h), alpha) / (4.0 * n_v);
}

}  // namespace glint::render::glossy
