#pragma once
// Ray/box slab test made conservative (Ize, "Robust BVH Ray Traversal", JCGT 2013): the far
// distance is enlarged by the worst-case rounding error of the slab computation, so a triangle
// touching a box face is never culled with its box. Together with the watertight triangle test this
// makes traversal watertight, not just the triangle test.
#include "accel/bvh_node.h"
#include "accel/ray.h"

namespace glint::accel {

// 1 + 2 * gamma(3), gamma(n) = n * eps / (1 - n * eps), eps = 2^-24 (pbrt's notation).
inline constexpr float kSlabFarScale = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);

struct BoxRay {
  vec3 origin;
  vec3 inv_direction;  // +-infinity for a zero component; its sign picks the near plane
};

GLINT_HOST_DEVICE inline BoxRay make_box_ray(const vec3& origin, const vec3& direction) {
  return {origin, vec3(1.0f / direction.x, 1.0f / direction.y, 1.0f / direction.z)};
}

// The ray's segment [t_near, t_far] inside the box [box_min, box_max], clamped to [t_min, t_max];
// false when it is empty. For a zero direction component with the origin on a slab plane, 0 * infinity
// gives NaN: the comparisons below are written so a NaN never wins, which ignores that axis, i.e. treats
// the ray as inside the slab (conservative). BVH and kd-tree traversal share it.
GLINT_HOST_DEVICE inline bool clip_to_box(const BoxRay& ray, const vec3& box_min, const vec3& box_max, float t_min,
                                          float t_max, float& t_near, float& t_far) {
  t_near = t_min;
  t_far = kInfinity;
  for (int axis = 0; axis < 3; ++axis) {
    const float inv = ray.inv_direction[axis];
    const float near_plane = inv < 0.0f ? box_max[axis] : box_min[axis];
    const float far_plane = inv < 0.0f ? box_min[axis] : box_max[axis];
    const float t0 = (near_plane - ray.origin[axis]) * inv;
    const float t1 = (far_plane - ray.origin[axis]) * inv;
    t_near = t0 > t_near ? t0 : t_near;
    t_far = t1 < t_far ? t1 : t_far;
  }
  // The ray's own t_max gets the same slack: a triangle hit at t <= t_max may lie on a face whose
  // computed entry distance rounds slightly above t_max.
  t_far = (t_far < t_max ? t_far : t_max) * kSlabFarScale;
  return t_near <= t_far;
}

// On a hit, returns true and the entry distance (clamped to t_min).
GLINT_HOST_DEVICE inline bool intersect_box(const BoxRay& ray, const BvhNode& node, float t_min, float t_max,
                                            float& t_entry) {
  float t_exit = 0.0f;
  return clip_to_box(ray, node.bounds_min, node.bounds_max, t_min, t_max, t_entry, t_exit);
}

}  // namespace glint::accel
