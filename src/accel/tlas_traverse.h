#pragma once
// Single-ray two-level traversal: walk the TLAS; at an instance leaf, move the ray into the
// instance's object space and walk its BLAS with the current closest t as the limit. Written once
// over the kind of BLAS: a BVH here (Blas), a kd-tree in kdtree/kdtree_tlas.h (KdBlas), each
// giving its structure view through blas_structure.
#include "accel/tlas.h"
#include "accel/traverse.h"

namespace glint::accel {

// Device-copyable view of a Tlas and the BLASes it references.
template <typename BlasT>
struct TwoLevelView {
  BvhView bvh;
  const Instance* instances = nullptr;
  const BlasT* blases = nullptr;
};

using TlasView = TwoLevelView<Blas>;

// The structure a BVH BLAS is walked through (intersect_closest/any of traverse.h).
GLINT_HOST_DEVICE inline const BvhView& blas_structure(const Blas& blas) { return blas.bvh; }

// A world ray's origin and direction in an instance's object space (an affine map, so t is the same
// in both spaces). Every two-level traversal (CPU binary and wide, GPU) enters a BLAS through this.
struct ObjectRay {
  vec3 origin;
  vec3 direction;
};

GLINT_HOST_DEVICE inline ObjectRay to_object_space(const Instance& instance, const Ray& ray) {
  return {vec3(instance.world_to_object * vec4(ray.origin, 1.0f)),
          vec3(instance.world_to_object * vec4(ray.direction, 0.0f))};
}

template <typename BlasT>
GLINT_HOST_DEVICE inline Hit trace_closest(const TwoLevelView<BlasT>& tlas, const Ray& ray) {
  Hit hit;
  float t_max = ray.t_max;
  traverse_bvh<false>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float& t_limit) {
    const Instance& instance = tlas.instances[index];
    const ObjectRay local = to_object_space(instance, ray);
    const BlasT& blas = tlas.blases[instance.blas];
    if (!intersect_closest(blas_structure(blas), blas.mesh, local.origin, local.direction, ray.t_min, t_limit, hit))
      return false;
    hit.instance = index;
    return true;
  });
  return hit;
}

// The same walk in any-hit mode: stops at the first triangle found in any instance.
template <typename BlasT>
GLINT_HOST_DEVICE inline bool trace_any(const TwoLevelView<BlasT>& tlas, const Ray& ray) {
  float t_max = ray.t_max;
  return traverse_bvh<true>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float&) {
    const Instance& instance = tlas.instances[index];
    const ObjectRay local = to_object_space(instance, ray);
    const BlasT& blas = tlas.blases[instance.blas];
    return intersect_any(blas_structure(blas), blas.mesh, local.origin, local.direction, ray.t_min, ray.t_max);
  });
}

}  // namespace glint::accel
