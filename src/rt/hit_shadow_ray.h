#pragma once
// The shadow ray from a reflection hit towards the point light: what a GPU backend writes for
// DeviceTracing::trace_closest_and_hit_shadows_device (cuda/gpu_hit_shadow_rays.cu) and what
// shaders/hit_shadow_rays.comp.glsl writes for the other backends; the two must stay the same rule:
//   n         = the hit triangle's geometric normal (world space), turned towards the reflection
//               ray's origin (the side the reflecting surface sees)
//   origin    = hit point + origin_offset * n
//   direction = light - origin (unnormalised), t in [0, kHitShadowRayEnd]: the light is at t = 1
// A miss, a degenerate triangle and a hit facing away from the light (unlit whatever the shadow
// says) get an empty ray (t_min > t_max), which is never occluded. The geometric normal, not the
// interpolated one, so the tracer needs only its own triangles (no vertex normals on the device).
#include "accel/ray.h"
#include "core/math.h"

namespace glint::rt {

inline constexpr float kHitShadowRayEnd = 1.0f - 1e-4f;

GLINT_HOST_DEVICE inline accel::Ray empty_shadow_ray() {
  accel::Ray ray;
  ray.origin = vec3(0.0f);
  ray.t_min = 1.0f;
  ray.direction = vec3(0.0f, 0.0f, 1.0f);
  ray.t_max = 0.0f;
  return ray;
}

// `p0..p2`: the hit triangle's world-space vertices; `u, v` the hit's barycentrics (accel::Hit).
GLINT_HOST_DEVICE inline accel::Ray hit_shadow_ray(const accel::Ray& reflection_ray, float u, float v, vec3 p0,
                                                   vec3 p1, vec3 p2, vec3 light, float origin_offset) {
  const vec3 point = (1.0f - u - v) * p0 + u * p1 + v * p2;
  vec3 n = glm::cross(p1 - p0, p2 - p0);
  const float length = glm::length(n);
  if (!(length > 0.0f)) return empty_shadow_ray();
  n /= length;
  if (glm::dot(n, -reflection_ray.direction) < 0.0f) n = -n;
  if (glm::dot(n, light - point) <= 0.0f) return empty_shadow_ray();
  accel::Ray ray;
  ray.origin = point + origin_offset * n;
  ray.t_min = 0.0f;
  ray.direction = light - ray.origin;
  ray.t_max = kHitShadowRayEnd;
  return ray;
}

}  // namespace glint::rt
