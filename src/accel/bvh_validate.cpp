#include "accel/bvh_validate.h"

#include "core/error.h"

#include <utility>
#include <vector>

namespace glint::accel {
namespace {

bool inside(const Aabb& inner, const Aabb& outer) {
  return inner.empty() || (outer.contains(inner.min) && outer.contains(inner.max));
}

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.empty() || b.empty() ||
         (a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
          a.min.z <= b.max.z && b.min.z <= a.max.z);
}

}  // namespace

void validate_bvh(const Bvh& bvh, std::span<const Aabb> prim_boxes, uint32_t max_leaf_size) {
  const size_t prim_count = prim_boxes.size();
  // Spatial-split structures (not refittable) hold references: a primitive may be in several leaves.
  const bool references = !bvh.refittable;
  const size_t slot_count = bvh.prim_indices.size();
  if (references ? slot_count < prim_count : slot_count != prim_count)
    fail("bvh: {} prim_indices for {} primitives", slot_count, prim_count);
  if (prim_count == 0) {
    if (!bvh.nodes.empty()) fail("bvh: {} nodes but no primitives", bvh.nodes.size());
    return;
  }
  if (bvh.nodes.empty()) fail("bvh: no nodes for {} primitives", prim_count);

  std::vector<uint8_t> prim_seen(prim_count, 0);
  std::vector<uint8_t> slot_seen(slot_count, 0);
  size_t reached = 0, leaves = 0, interior = 0;
  uint32_t max_depth = 0;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 1u}};
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    ++reached;
    max_depth = std::max(max_depth, depth);
    if (depth > kMaxBvhDepth) fail("bvh: node {} at depth {} beyond the limit {}", index, depth, kMaxBvhDepth);
    const BvhNode& node = bvh.nodes[index];
    const Aabb box = node.bounds();
    if (node.is_leaf()) {
      ++leaves;
      if (node.prim_count > max_leaf_size)
        fail("bvh: leaf {} holds {} primitives, more than {}", index, node.prim_count, max_leaf_size);
      if (size_t{node.first} + node.prim_count > slot_count)
        fail("bvh: leaf {} slots [{}, {}) past the end {}", index, node.first, node.first + node.prim_count, slot_count);
      for (uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot) {
        if (slot_seen[slot]++) fail("bvh: slot {} used by two leaves", slot);
        const uint32_t prim = bvh.prim_indices[slot];
        if (prim >= prim_count) fail("bvh: slot {} references primitive {} of {}", slot, prim, prim_count);
        if (prim_seen[prim]++ && !references) fail("bvh: primitive {} referenced twice", prim);
        // A reference's box is the clipped part of its primitive: it overlaps, need not contain.
        if (references ? !overlaps(prim_boxes[prim], box) : !inside(prim_boxes[prim], box))
          fail("bvh: primitive {} is not inside its leaf {}", prim, index);
      }
      continue;
    }
    ++interior;
    if (node.left() <= index || size_t{node.right()} >= bvh.nodes.size())
      fail("bvh: interior node {} has children at {} (need index > parent and < {})", index, node.left(),
           bvh.nodes.size());
    for (uint32_t child : {node.left(), node.right()}) {
      if (!inside(bvh.nodes[child].bounds(), box)) fail("bvh: child {} is not inside its parent {}", child, index);
      stack.push_back({child, depth + 1});
    }
    if (reached > bvh.nodes.size()) fail("bvh: a node is reached twice (cycle or shared child)");
  }
  for (size_t slot = 0; slot < slot_count; ++slot)
    if (!slot_seen[slot]) fail("bvh: slot {} is in no leaf", slot);
  if (reached != bvh.nodes.size()) fail("bvh: {} nodes reachable of {} stored", reached, bvh.nodes.size());
  if (interior + 1 != leaves) fail("bvh: {} interior nodes for {} leaves", interior, leaves);
  for (size_t prim = 0; prim < prim_count; ++prim)
    if (!prim_seen[prim]) fail("bvh: primitive {} is in no leaf", prim);
  if (max_depth != bvh.depth) fail("bvh: depth {} recorded as {}", max_depth, bvh.depth);
}

}  // namespace glint::accel
