#include "accel/kdtree/kdtree_validate.h"

#include "accel/builders/primitive_bounds.h"
#include "core/error.h"

#include <algorithm>
#include <vector>

namespace glint::accel {
namespace {

// Closed boxes grown by a few ulps: sample points are rounded, and triangles touching a cell's face
// count as overlapping it.
Aabb with_slack(const Aabb& box) {
  const vec3 slack = 4e-7f * (glm::abs(box.min) + glm::abs(box.max)) + vec3(1e-30f);
  return Aabb{box.min - slack, box.max + slack};
}

bool overlaps(const Aabb& a, const Aabb& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
         b.min.z <= a.max.z;
}

}  // namespace

void validate_kdtree(const KdTree& tree, const TriangleMesh& mesh, uint32_t depth_limit) {
  const uint32_t count = mesh.triangle_count;
  if (tree.prim_count != count) fail("kdtree: built over {} triangles, mesh has {}", tree.prim_count, count);
  if (count == 0) {
    if (!tree.nodes.empty() || !tree.prim_indices.empty()) fail("kdtree: nodes or references but no triangles");
    return;
  }
  if (tree.nodes.empty()) fail("kdtree: no nodes for {} triangles", count);
  std::vector<Aabb> boxes(count);
  triangle_boxes(mesh, boxes);
  Aabb all;
  for (const Aabb& box : boxes) all.extend(box);
  if (all.min != tree.bounds.min || all.max != tree.bounds.max) fail("kdtree: bounds are not the triangles' bounds");

  struct Item {
    uint32_t node;
    uint32_t depth;
    Aabb cell;
  };
  std::vector<uint8_t> node_seen(tree.nodes.size(), 0), slot_seen(tree.prim_indices.size(), 0);
  std::vector<std::vector<Aabb>> cells_of(count);  // the cells of the leaves referencing each triangle
  uint32_t max_depth = 0;
  std::vector<Item> stack{{0u, 1u, tree.bounds}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    if (item.node >= tree.nodes.size()) fail("kdtree: node index {} past the end {}", item.node, tree.nodes.size());
    if (node_seen[item.node]++) fail("kdtree: node {} reached twice", item.node);
    max_depth = std::max(max_depth, item.depth);
    if (item.depth > std::min(depth_limit, kMaxKdDepth))
      fail("kdtree: node {} at depth {} beyond the limit {}", item.node, item.depth, depth_limit);
    const KdNode& node = tree.nodes[item.node];
    if (node.is_leaf()) {
      const size_t end = size_t{node.first_prim} + node.prim_count();
      if (end > tree.prim_indices.size()) fail("kdtree: leaf {} slots past the end", item.node);
      for (size_t slot = node.first_prim; slot != end; ++slot) {
        if (slot_seen[slot]++) fail("kdtree: slot {} used by two leaves", slot);
        const uint32_t prim = tree.prim_indices[slot];
        if (prim >= count) fail("kdtree: slot {} references triangle {} of {}", slot, prim, count);
        if (!overlaps(boxes[prim], with_slack(item.cell)))
          fail("kdtree: triangle {} does not overlap the cell of its leaf {}", prim, item.node);
        cells_of[prim].push_back(item.cell);
      }
      continue;
    }
    const int axis = node.axis();
    if (!(node.split > item.cell.min[axis] && node.split < item.cell.max[axis]))
      fail("kdtree: node {} splits axis {} at {} outside its cell [{}, {}]", item.node, axis, node.split,
           item.cell.min[axis], item.cell.max[axis]);
    if (node.above_child() <= item.node + 1)
      fail("kdtree: node {} has its above child at {}, not after its below child", item.node, node.above_child());
    Aabb below = item.cell, above = item.cell;
    below.max[axis] = node.split;
    above.min[axis] = node.split;
    stack.push_back({item.node + 1, item.depth + 1, below});
    stack.push_back({node.above_child(), item.depth + 1, above});
  }
  for (size_t i = 0; i < node_seen.size(); ++i)
    if (!node_seen[i]) fail("kdtree: node {} is unreachable", i);
  for (size_t i = 0; i < slot_seen.size(); ++i)
    if (!slot_seen[i]) fail("kdtree: slot {} is in no leaf", i);
  if (max_depth != tree.depth) fail("kdtree: depth {} recorded as {}", max_depth, tree.depth);

  for (uint32_t prim = 0; prim < count; ++prim) {
    const Triangle tri = mesh.triangle(prim);
    const vec3 points[] = {tri.v0, tri.v1, tri.v2, 0.5f * (tri.v0 + tri.v1), 0.5f * (tri.v1 + tri.v2),
                           0.5f * (tri.v2 + tri.v0), (tri.v0 + tri.v1 + tri.v2) / 3.0f};
    for (const vec3& point : points) {
      const bool covered = std::any_of(cells_of[prim].begin(), cells_of[prim].end(),
                                       [&](const Aabb& cell) { return with_slack(cell).contains(point); });
      if (!covered)
        fail("kdtree: point ({}, {}, {}) of triangle {} is in none of the {} cells referencing it", point.x, point.y,
             point.z, prim, cells_of[prim].size());
    }
  }
}

}  // namespace glint::accel
