#pragma once
// Single-ray BVH traversal on the GPU, one thread per ray, closest hit or any hit (occlusion). The same algorithm as accel/traverse.h
// (depth first, nearer child first, the farther child pushed with its entry distance and skipped on
// pop once a closer hit is known) and the same conservative box and watertight triangle tests, so
// the hits equal the CPU backend's; what differs is what the GPU needs:
//  - a node pair is fetched as four 16-byte read-only loads (siblings are adjacent in the layout);
//  - the stack is guarded: GPU builders (ploc) do not bound their depth in advance, so a push past
//    kGpuStackSize sets `overflow` (reported as an error by the caller) instead of writing past the
//    stack. CPU builders and lbvh never get there (depth <= accel::kMaxBvhDepth).
// CUDA-only header: include it from .cu files.
#include "accel/bvh_node.h"
#include "accel/intersect_box.h"
#include "accel/intersect_triangle.h"
#include "accel/kdtree/kdtree_tlas.h"
#include "accel/ray.h"
#include "accel/tlas_traverse.h"
#include "accel/traverse.h"

#include <cstdint>

namespace glint::cuda {

inline constexpr uint32_t kGpuStackSize = accel::kMaxBvhDepth;

// The node's box and payload through the read-only cache.
__device__ inline accel::BvhNode load_node(const accel::BvhNode* nodes, uint32_t index) {
  const float4* raw = reinterpret_cast<const float4*>(nodes + index);
  const float4 low = __ldg(raw);
  const float4 high = __ldg(raw + 1);
  accel::BvhNode node;
  node.bounds_min = vec3(low.x, low.y, low.z);
  node.first = __float_as_uint(low.w);
  node.bounds_max = vec3(high.x, high.y, high.z);
  node.prim_count = __float_as_uint(high.w);
  return node;
}

// Visits the primitives of the leaves the segment [t_min, t_max] enters, nearest subtree first;
// intersect_prim(prim, t_max) returns true on a hit and may lower t_max. Returns whether anything
// was hit; sets overflow (and stops) when the stack would overflow. With kAnyHit (a compile-time
// switch, so the closest-hit kernel is unchanged), returns true at the first hit.
template <bool kAnyHit, typename IntersectPrim>
__device__ inline bool gpu_traverse_bvh(const accel::BvhView& bvh, const vec3& origin, const vec3& direction,
                                        float t_min, float& t_max, bool& overflow, IntersectPrim&& intersect_prim) {
  if (bvh.node_count == 0) return false;
  const accel::BoxRay box_ray = accel::make_box_ray(origin, direction);
  float t_entry;
  if (!accel::intersect_box(box_ray, load_node(bvh.nodes, 0), t_min, t_max, t_entry)) return false;

  uint32_t stack_node[kGpuStackSize];
  float stack_entry[kGpuStackSize];
  uint32_t stack_size = 0;
  accel::BvhNode node = load_node(bvh.nodes, 0);
  bool hit = false;
  for (;;) {
    if (node.is_leaf()) {
      const uint32_t end = node.first + node.prim_count;
      for (uint32_t slot = node.first; slot != end; ++slot) {
        if (intersect_prim(__ldg(bvh.prim_indices + slot), t_max)) {
          hit = true;
          if constexpr (kAnyHit) return true;
        }
      }
    } else {
      const accel::BvhNode left = load_node(bvh.nodes, node.left());
      const accel::BvhNode right = load_node(bvh.nodes, node.right());
      float t_left, t_right;
      const bool hit_left = accel::intersect_box(box_ray, left, t_min, t_max, t_left);
      const bool hit_right = accel::intersect_box(box_ray, right, t_min, t_max, t_right);
      if (hit_left && hit_right) {
        if (stack_size == kGpuStackSize) {
          overflow = true;
          return hit;
        }
        // The occlusion query stops at any hit, so the order cannot change its answer: it walks
        // left first and keeps no entry distances.
        const bool right_first = !kAnyHit && t_right < t_left;
        stack_node[stack_size] = right_first ? node.left() : node.right();
        if constexpr (!kAnyHit) stack_entry[stack_size] = right_first ? t_left : t_right;
        ++stack_size;
        node = right_first ? right : left;
        continue;
      }
      if (hit_left || hit_right) {
        node = hit_left ? left : right;
        continue;
      }
    }
    // Pop the next subtree that may still hold something closer than t_max (with the box test's
    // slack). The occlusion query's t_max never falls before it returns, and a pushed entry is at
    // most the box's exit, itself at most t_max with that slack: every subtree passes the test.
    // (Testing the popped node's box again instead of stacking entries, as the gl backend's walk
    // does, was slower here: docs/perf.md "Ninth round".)
    for (;;) {
      if (stack_size == 0) return hit;
      --stack_size;
      if constexpr (kAnyHit) break;
      if (stack_entry[stack_size] <= t_max * accel::kSlabFarScale) break;
    }
    node = load_node(bvh.nodes, stack_node[stack_size]);
  }
}

// Closest hit in one BLAS (object space). Updates `hit` (t, prim, u, v) when something closer than
// t_max is found, with the CPU traversal's step and tie rule (accel::record_closer_hit).
__device__ inline bool gpu_intersect_closest(const accel::Blas& blas, const vec3& origin, const vec3& direction,
                                             float t_min, float& t_max, accel::Hit& hit, bool& overflow) {
  const accel::WatertightRay ray = accel::make_watertight_ray(origin, direction);
  return gpu_traverse_bvh<false>(blas.bvh, origin, direction, t_min, t_max, overflow,
                                 [&](uint32_t prim, float& t_limit) {
    return accel::record_closer_hit(ray, blas.mesh, prim, t_min, t_limit, hit);
  });
}

// Whether anything in one BLAS (object space) lies within [t_min, t_max]; stops at the first hit.
__device__ inline bool gpu_intersect_any(const accel::Blas& blas, const vec3& origin, const vec3& direction,
                                         float t_min, float t_max, bool& overflow) {
  const accel::WatertightRay ray = accel::make_watertight_ray(origin, direction);
  return gpu_traverse_bvh<true>(blas.bvh, origin, direction, t_min, t_max, overflow,
                                [&](uint32_t prim, float& t_limit) {
    accel::TriangleHit tri_hit;
    return accel::intersect_triangle(ray, blas.mesh.triangle(prim), t_min, t_limit, tri_hit);
  });
}

// A kd-tree BLAS (AccelOptions::blas = kdtree) entered by the same two-level walk: accel's
// object-space kd-tree walk (accel/kdtree/kdtree_traverse.h: front to back, its stack bounded by the
// builder's depth limit, so it needs no guard and never sets `overflow`).
__device__ inline bool gpu_intersect_closest(const accel::KdBlas& blas, const vec3& origin, const vec3& direction,
                                             float t_min, float& t_max, accel::Hit& hit, bool& /*overflow*/) {
  return accel::intersect_closest(blas.tree, blas.mesh, origin, direction, t_min, t_max, hit);
}

__device__ inline bool gpu_intersect_any(const accel::KdBlas& blas, const vec3& origin, const vec3& direction,
                                         float t_min, float t_max, bool& /*overflow*/) {
  return accel::intersect_any(blas.tree, blas.mesh, origin, direction, t_min, t_max);
}

// Two levels: the TLAS over instances (guarded walk), each instance's BLAS (a BVH: accel::TlasView,
// or a kd-tree: accel::KdTlasView) entered with the ray moved into its object space (t is the same
// in both spaces) through the gpu_intersect_closest/any overload for its kind. Hit.instance is the
// instance index.
template <typename BlasT>
__device__ inline accel::Hit gpu_trace_closest(const accel::TwoLevelView<BlasT>& tlas, const accel::Ray& ray,
                                               bool& overflow) {
  accel::Hit hit;
  float t_max = ray.t_max;
  gpu_traverse_bvh<false>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, overflow,
                          [&](uint32_t index, float& t_limit) {
    const accel::Instance& instance = tlas.instances[index];
    const accel::ObjectRay local = accel::to_object_space(instance, ray);
    if (!gpu_intersect_closest(tlas.blases[instance.blas], local.origin, local.direction, ray.t_min, t_limit, hit,
                               overflow))
      return false;
    hit.instance = index;
    return true;
  });
  return hit;
}

// The occlusion query through both levels: true at the first triangle found within [t_min, t_max] in
// any instance (the same walk in any-hit mode, the same stack guard).
template <typename BlasT>
__device__ inline bool gpu_trace_any(const accel::TwoLevelView<BlasT>& tlas, const accel::Ray& ray, bool& overflow) {
  float t_max = ray.t_max;
  return gpu_traverse_bvh<true>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, overflow,
                                [&](uint32_t index, float&) {
    const accel::Instance& instance = tlas.instances[index];
    const accel::ObjectRay local = accel::to_object_space(instance, ray);
    return gpu_intersect_any(tlas.blases[instance.blas], local.origin, local.direction, ray.t_min, ray.t_max,
                             overflow);
  });
}

}  // namespace glint::cuda
