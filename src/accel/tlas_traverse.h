#pragma once
// Single-ray two-level traversal: walk the TLAS; at an instance leaf, move the ray into the
// instance's object space and walk its BLAS with the current closest t as the limit.
#include "accel/tlas.h"
#include "accel/traverse.h"

namespace glint::accel {

// Device-copyable view of a Tlas and the BLASes it references.
struct TlasView {
  BvhView bvh;
  const Instance* instances = nullptr;
  const Blas* blases = nullptr;
};

GLINT_HOST_DEVICE inline Hit trace_closest(const TlasView& tlas, const Ray& ray) {
  Hit hit;
  float t_max = ray.t_max;
  traverse_bvh<false>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float& t_limit) {
    const Instance& instance = tlas.instances[index];
    const vec3 origin(instance.world_to_object * vec4(ray.origin, 1.0f));
    const vec3 direction(instance.world_to_object * vec4(ray.direction, 0.0f));
    const Blas& blas = tlas.blases[instance.blas];
    if (!intersect_closest(blas.bvh, blas.mesh, origin, direction, ray.t_min, t_limit, hit)) return false;
    hit.instance = index;
    return true;
  });
  return hit;
}

GLINT_HOST_DEVICE inline bool trace_any(const TlasView& tlas, const Ray& ray) {
  float t_max = ray.t_max;
  return traverse_bvh<true>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float&) {
    const Instance& instance = tlas.instances[index];
    const vec3 origin(instance.world_to_object * vec4(ray.origin, 1.0f));
    const vec3 direction(instance.world_to_object * vec4(ray.direction, 0.0f));
    const Blas& blas = tlas.blases[instance.blas];
    return intersect_any(blas.bvh, blas.mesh, origin, direction, ray.t_min, ray.t_max);
  });
}

}  // namespace glint::accel
