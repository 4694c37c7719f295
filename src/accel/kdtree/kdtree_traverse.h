#pragma once
// Single-ray kd-tree traversal, host and device: the classic front-to-back descent (pbrt, Havran's
// thesis) with a fixed stack of far cells and their [t_near, t_far]. Because cells do not overlap,
// closest hit stops at the first leaf whose hit lies within the leaf's own t range, i.e. before
// the entry of the next cell on the stack.
//
// Robustness: every decision that could skip a cell (plane beyond t_far, before t_near, a popped
// cell beyond the best hit) is made with the slab test's rounding slack (kSlabFarScale), so a
// triangle touching a split plane is reached from either side; a ray lying in a split plane visits
// both children.
#include "accel/intersect_box.h"
#include "accel/intersect_triangle.h"
#include "accel/kdtree/kdtree.h"
#include "accel/ray.h"
#include "accel/traverse.h"

namespace glint::accel {

// Calls intersect_prim(prim, t_max) for the triangles of the leaves the ray segment crosses, front
// to back; it returns true on a hit and may lower t_max. With kAnyHit, stops at the first hit.
template <bool kAnyHit, typename IntersectPrim>
GLINT_HOST_DEVICE bool traverse_kdtree(const KdTreeView& tree, const vec3& origin, const vec3& direction, float t_min,
                                       float& t_max, IntersectPrim&& intersect_prim) {
  if (tree.node_count == 0) return false;
  const BoxRay box_ray = make_box_ray(origin, direction);
  float t_near, t_far;
  if (!clip_to_box(box_ray, tree.bounds.min, tree.bounds.max, t_min, t_max, t_near, t_far)) return false;

  uint32_t stack_node[kMaxKdDepth];
  float stack_near[kMaxKdDepth], stack_far[kMaxKdDepth];
  uint32_t stack_size = 0;
  uint32_t index = 0;
  bool hit = false;
  for (;;) {
    const KdNode& node = tree.nodes[index];
    if (!node.is_leaf()) {
      const int axis = node.axis();
      const float o = origin[axis];
      // An origin on the plane counts as on the side the ray comes from: then t_split = 0 and the
      // general case below visits that side for t <= 0 (when the ray starts there) and the other after.
      const bool below_first = o < node.split || (o == node.split && direction[axis] > 0.0f);
      const uint32_t first = below_first ? index + 1 : node.above_child();
      const uint32_t second = below_first ? node.above_child() : index + 1;
      const float t_split = (node.split - o) * box_ray.inv_direction[axis];
      if (t_split != t_split) {
        // 0 * infinity: the ray lies in the plane; both children, same range.
        stack_node[stack_size] = second;
        stack_near[stack_size] = t_near;
        stack_far[stack_size] = t_far;
        ++stack_size;
        index = first;
      } else if (t_split < 0.0f || t_split > t_far * kSlabFarScale) {
        index = first;  // moving away from the plane, or leaving the cell before reaching it
      } else if (t_split * kSlabFarScale < t_near) {
        index = second;  // crossed the plane before entering the cell
      } else {
        stack_node[stack_size] = second;
        stack_near[stack_size] = t_split;
        stack_far[stack_size] = t_far;
        ++stack_size;
        index = first;
        t_far = t_split;
      }
      continue;
    }
    const uint32_t end = node.first_prim + node.prim_count();
    for (uint32_t slot = node.first_prim; slot != end; ++slot) {
      if (intersect_prim(tree.prim_indices[slot], t_max)) {
        hit = true;
        if constexpr (kAnyHit) return true;
      }
    }
    // Early termination: a far cell is entered no earlier than its stack entry says, so once the
    // best hit lies before that entry the cell is dropped unvisited; when the hit lies inside the
    // current cell, every cell along the ray is dropped this way. Each entry is checked, not only
    // the top one: the twin of a cell whose split plane contains the ray shares that cell's t range
    // and sits below entries with later starts.
    for (;;) {
      if (stack_size == 0) return hit;
      --stack_size;
      if (stack_near[stack_size] <= t_max * kSlabFarScale) break;
    }
    index = stack_node[stack_size];
    t_near = stack_near[stack_size];
    t_far = stack_far[stack_size];
  }
}

// As accel/traverse.h's intersect_closest for a BVH (what a two-level walk calls per instance, in
// object space): updates `hit` (t, prim, u, v; instance untouched) only when something closer than
// t_max is found, with record_closer_hit's tie rule, and lowers t_max to it.
GLINT_HOST_DEVICE inline bool intersect_closest(const KdTreeView& tree, const TriangleMesh& mesh, const vec3& origin,
                                                const vec3& direction, float t_min, float& t_max, Hit& hit) {
  const WatertightRay ray = make_watertight_ray(origin, direction);
  return traverse_kdtree<false>(tree, origin, direction, t_min, t_max, [&](uint32_t prim, float& t_limit) {
    return record_closer_hit(ray, mesh, prim, t_min, t_limit, hit);
  });
}

GLINT_HOST_DEVICE inline bool intersect_any(const KdTreeView& tree, const TriangleMesh& mesh, const vec3& origin,
                                            const vec3& direction, float t_min, float t_max) {
  const WatertightRay ray = make_watertight_ray(origin, direction);
  return traverse_kdtree<true>(tree, origin, direction, t_min, t_max, [&](uint32_t prim, float& t_limit) {
    TriangleHit tri_hit;
    return intersect_triangle(ray, mesh.triangle(prim), t_min, t_limit, tri_hit);
  });
}

GLINT_HOST_DEVICE inline Hit trace_closest(const KdTreeView& tree, const TriangleMesh& mesh, const Ray& ray) {
  const WatertightRay tri_ray = make_watertight_ray(ray.origin, ray.direction);
  Hit hit;
  float t_max = ray.t_max;
  traverse_kdtree<false>(tree, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t prim, float& t_limit) {
    TriangleHit tri_hit;
    if (!intersect_triangle(tri_ray, mesh.triangle(prim), ray.t_min, t_limit, tri_hit)) return false;
    // Equal t: keep the first one found (a triangle in two leaves is found twice at the same t).
    if (tri_hit.t == t_limit && hit.valid()) return false;
    t_limit = tri_hit.t;
    hit = Hit{tri_hit.t, 0u, prim, tri_hit.u, tri_hit.v};
    return true;
  });
  return hit;
}

GLINT_HOST_DEVICE inline bool trace_any(const KdTreeView& tree, const TriangleMesh& mesh, const Ray& ray) {
  const WatertightRay tri_ray = make_watertight_ray(ray.origin, ray.direction);
  float t_max = ray.t_max;
  return traverse_kdtree<true>(tree, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t prim, float& t_limit) {
    TriangleHit tri_hit;
    return intersect_triangle(tri_ray, mesh.triangle(prim), ray.t_min, t_limit, tri_hit);
  });
}

}  // namespace glint::accel
