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

// The kd-tree under the walk name of accel/traverse.h, which writes intersect_closest/any and
// trace_closest/any once for every structure: through a KdTreeView they walk this tree.
template <>
inline constexpr bool kIsStructureView<KdTreeView> = true;

template <bool kAnyHit, typename IntersectPrim>
GLINT_HOST_DEVICE inline bool walk_structure(const KdTreeView& tree, const vec3& origin, const vec3& direction,
                                             float t_min, float& t_max, IntersectPrim&& intersect_prim) {
  return traverse_kdtree<kAnyHit>(tree, origin, direction, t_min, t_max, intersect_prim);
}

}  // namespace glint::accel
