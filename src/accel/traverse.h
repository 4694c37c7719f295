#pragma once
// Single-ray BVH traversal, shared by CPU batches and (later) CUDA kernels: depth-first, nearer
// child first, the farther child pushed on a fixed stack with its entry distance so it can be
// skipped on pop once a closer hit has been found. Builders keep depth <= kMaxBvhDepth, so the
// stack (one entry per level at most) cannot overflow.
#include "accel/bvh_node.h"
#include "accel/intersect_box.h"
#include "accel/intersect_triangle.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

namespace glint::accel {

// Visits the leaves' primitives whose boxes the ray segment [t_min, t_max] enters. For every one,
// calls intersect_prim(prim, t_max), which returns true on a hit and may lower t_max (closest hit).
// With kAnyHit, stops at the first hit. Returns whether anything was hit.
template <bool kAnyHit, typename IntersectPrim>
GLINT_HOST_DEVICE bool traverse_bvh(const BvhView& bvh, const vec3& origin, const vec3& direction, float t_min,
                                    float& t_max, IntersectPrim&& intersect_prim) {
  if (bvh.node_count == 0) return false;
  const BoxRay box_ray = make_box_ray(origin, direction);
  float t_entry;
  if (!intersect_box(box_ray, bvh.nodes[0], t_min, t_max, t_entry)) return false;

  uint32_t stack_node[kMaxBvhDepth];
  float stack_entry[kMaxBvhDepth];
  uint32_t stack_size = 0;
  uint32_t index = 0;
  bool hit = false;
  for (;;) {
    const BvhNode& node = bvh.nodes[index];
    if (node.is_leaf()) {
      const uint32_t end = node.first + node.prim_count;
      for (uint32_t slot = node.first; slot != end; ++slot) {
        if (intersect_prim(bvh.prim_indices[slot], t_max)) {
          hit = true;
          if constexpr (kAnyHit) return true;
        }
      }
    } else {
      float t_left, t_right;
      const bool hit_left = intersect_box(box_ray, bvh.nodes[node.left()], t_min, t_max, t_left);
      const bool hit_right = intersect_box(box_ray, bvh.nodes[node.right()], t_min, t_max, t_right);
      if (hit_left && hit_right) {
        const bool right_first = t_right < t_left;
        stack_node[stack_size] = right_first ? node.left() : node.right();
        stack_entry[stack_size] = right_first ? t_left : t_right;
        ++stack_size;
        index = right_first ? node.right() : node.left();
        continue;
      }
      if (hit_left || hit_right) {
        index = hit_left ? node.left() : node.right();
        continue;
      }
    }
    // Pop the next subtree that may still hold something closer than the current t_max (with the
    // same slack as the box test).
    for (;;) {
      if (stack_size == 0) return hit;
      --stack_size;
      if (stack_entry[stack_size] <= t_max * kSlabFarScale) break;
    }
    index = stack_node[stack_size];
  }
}

// The walk of one single-mesh structure under the name the queries below call: one overload per
// structure view (kdtree/kdtree_traverse.h adds the kd-tree's), so intersect_closest/any and
// trace_closest/any are written once for every structure and stay inlined into each walk.
// kIsStructureView marks the views that have one (the queries take nothing else).
template <typename View>
inline constexpr bool kIsStructureView = false;
template <>
inline constexpr bool kIsStructureView<BvhView> = true;

template <bool kAnyHit, typename IntersectPrim>
GLINT_HOST_DEVICE inline bool walk_structure(const BvhView& bvh, const vec3& origin, const vec3& direction,
                                             float t_min, float& t_max, IntersectPrim&& intersect_prim) {
  return traverse_bvh<kAnyHit>(bvh, origin, direction, t_min, t_max, intersect_prim);
}

// The closest-hit step at one triangle, shared by every BVH traversal (CPU, GPU): when triangle
// `prim` is hit within [t_min, t_limit] and closer than the current hit, records it in `hit` (t, prim,
// u, v), lowers t_limit and returns true. Equal t keeps the first one found (ties on shared edges may
// go either way).
GLINT_HOST_DEVICE inline bool record_closer_hit(const WatertightRay& ray, const TriangleMesh& mesh, uint32_t prim,
                                                float t_min, float& t_limit, Hit& hit) {
  TriangleHit tri_hit;
  if (!intersect_triangle(ray, mesh.triangle(prim), t_min, t_limit, tri_hit)) return false;
  if (tri_hit.t == t_limit && hit.valid()) return false;
  t_limit = tri_hit.t;
  hit.t = tri_hit.t;
  hit.prim = prim;
  hit.u = tri_hit.u;
  hit.v = tri_hit.v;
  return true;
}

// Closest hit against one triangle mesh through `structure` (a BvhView or a KdTreeView: anything
// walk_structure takes). Updates `hit` (t, prim, u, v; instance untouched) only when something
// closer than t_max is found, lowers t_max to it and returns whether it was. What a two-level walk
// calls per instance, in object space.
template <typename StructureView>
  requires kIsStructureView<StructureView>
GLINT_HOST_DEVICE inline bool intersect_closest(const StructureView& structure, const TriangleMesh& mesh,
                                                const vec3& origin, const vec3& direction, float t_min, float& t_max,
                                                Hit& hit) {
  const WatertightRay ray = make_watertight_ray(origin, direction);
  return walk_structure<false>(structure, origin, direction, t_min, t_max, [&](uint32_t prim, float& t_limit) {
    return record_closer_hit(ray, mesh, prim, t_min, t_limit, hit);
  });
}

// Whether anything of the mesh lies within [t_min, t_max]; stops at the first hit.
template <typename StructureView>
  requires kIsStructureView<StructureView>
GLINT_HOST_DEVICE inline bool intersect_any(const StructureView& structure, const TriangleMesh& mesh,
                                            const vec3& origin, const vec3& direction, float t_min, float t_max) {
  const WatertightRay ray = make_watertight_ray(origin, direction);
  return walk_structure<true>(structure, origin, direction, t_min, t_max, [&](uint32_t prim, float& t_limit) {
    TriangleHit tri_hit;
    return intersect_triangle(ray, mesh.triangle(prim), t_min, t_limit, tri_hit);
  });
}

// Single-level conveniences: Hit.instance is 0 on a hit.
template <typename StructureView>
  requires kIsStructureView<StructureView>
GLINT_HOST_DEVICE inline Hit trace_closest(const StructureView& structure, const TriangleMesh& mesh, const Ray& ray) {
  Hit hit;
  float t_max = ray.t_max;
  if (intersect_closest(structure, mesh, ray.origin, ray.direction, ray.t_min, t_max, hit)) hit.instance = 0;
  return hit;
}

template <typename StructureView>
  requires kIsStructureView<StructureView>
GLINT_HOST_DEVICE inline bool trace_any(const StructureView& structure, const TriangleMesh& mesh, const Ray& ray) {
  return intersect_any(structure, mesh, ray.origin, ray.direction, ray.t_min, ray.t_max);
}

}  // namespace glint::accel
