// Wald & Havran 2006, section 4.3/5: the O(N log N) kd-tree builder. Split candidates are the
// "events" where a triangle's box, clipped to the node's cell, starts, ends or lies flat (planar).
// They are sorted once at the root; at every node one sweep per axis finds the SAH-best plane, and
// the sorted event list is split between the children in linear time: events of triangles wholly on
// one side keep their order, only triangles straddling the plane are clipped to each child's cell
// (perfect splits) and their new events sorted and merged in.
#include "accel/kdtree/kdtree.h"

#include "accel/builders/primitive_bounds.h"
#include "core/error.h"
#include "core/stopwatch.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace glint::accel {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

enum EventType : uint8_t { kEnd = 0, kPlanar = 1, kStart = 2 };  // sweep order at equal positions

struct Event {
  float position;
  uint32_t prim;  // index into the node's local triangle list
  uint8_t axis;
  uint8_t type;
};

bool event_less(const Event& a, const Event& b) {
  if (a.axis != b.axis) return a.axis < b.axis;
  if (a.position != b.position) return a.position < b.position;
  return a.type < b.type;
}

// The triangles of a node: global triangle index and its box clipped to the node's cell.
struct NodeInput {
  std::vector<uint32_t> prims;
  std::vector<Aabb> boxes;
  std::vector<Event> events;  // sorted by event_less
};

void add_events(const Aabb& box, uint32_t local, std::vector<Event>& events) {
  for (uint8_t axis = 0; axis < 3; ++axis) {
    if (box.min[axis] == box.max[axis]) {
      events.push_back({box.min[axis], local, axis, kPlanar});
    } else {
      events.push_back({box.min[axis], local, axis, kStart});
      events.push_back({box.max[axis], local, axis, kEnd});
    }
  }
}

// Sutherland-Hodgman clipping of the triangle to `cell` in double (clipped-off slivers are far
// below float resolution), returning the float box rounded outward; empty when nothing is left.
Aabb clip_triangle(const Triangle& tri, const Aabb& cell) {
  glm::dvec3 polygon[9] = {glm::dvec3(tri.v0), glm::dvec3(tri.v1), glm::dvec3(tri.v2)};
  int count = 3;
  glm::dvec3 next[9];
  for (int axis = 0; axis < 3 && count > 0; ++axis) {
    for (int side = 0; side < 2 && count > 0; ++side) {
      const double plane = side == 0 ? cell.min[axis] : cell.max[axis];
      const auto inside = [&](const glm::dvec3& p) { return side == 0 ? p[axis] >= plane : p[axis] <= plane; };
      int out = 0;
      for (int i = 0; i < count; ++i) {
        const glm::dvec3& a = polygon[i];
        const glm::dvec3& b = polygon[(i + 1) % count];
        const bool a_in = inside(a), b_in = inside(b);
        if (a_in) next[out++] = a;
        if (a_in != b_in) {
          glm::dvec3 crossing = a + (b - a) * ((plane - a[axis]) / (b[axis] - a[axis]));
          crossing[axis] = plane;
          next[out++] = crossing;
        }
      }
      count = out;
      std::copy(next, next + count, polygon);
    }
  }
  Aabb box;
  for (int i = 0; i < count; ++i)
    for (int axis = 0; axis < 3; ++axis) {
      const auto value = static_cast<float>(polygon[i][axis]);
      box.min[axis] = std::min(box.min[axis], double(value) > polygon[i][axis] ? std::nextafter(value, -kInf) : value);
      box.max[axis] = std::max(box.max[axis], double(value) < polygon[i][axis] ? std::nextafter(value, kInf) : value);
    }
  return box;
}

Aabb intersect(const Aabb& a, const Aabb& b) { return Aabb{glm::max(a.min, b.min), glm::min(a.max, b.max)}; }

// A node of the tree under construction; flattened to KdNode once built.
struct TempNode {
  int axis = -1;  // -1: leaf
  float split = 0.0f;
  std::vector<uint32_t> prims;  // leaf: global triangle indices
  std::unique_ptr<TempNode> below, above;
};

struct Plane {
  float cost = kInf;
  int axis = -1;
  float position = 0.0f;
  bool planar_left = true;
};

struct Builder {
  const TriangleMesh& mesh;
  const KdTreeOptions& options;
  uint32_t max_depth;

  float surface(const Aabb& box) const { return half_area(box); }

  // One sweep over the sorted events (all three axes, one after the other).
  Plane find_plane(const NodeInput& input, const Aabb& cell) const {
    Plane best;
    const float area = surface(cell);
    if (!(area > 0.0f)) return best;
    const auto n = static_cast<uint32_t>(input.prims.size());
    const std::vector<Event>& events = input.events;
    size_t i = 0;
    while (i < events.size()) {
      const int axis = events[i].axis;
      uint32_t left = 0, right = n;
      while (i < events.size() && events[i].axis == axis) {
        const float position = events[i].position;
        uint32_t ends = 0, planars = 0, starts = 0;
        while (i < events.size() && events[i].axis == axis && events[i].position == position && events[i].type == kEnd)
          ++ends, ++i;
        while (i < events.size() && events[i].axis == axis && events[i].position == position &&
               events[i].type == kPlanar)
          ++planars, ++i;
        while (i < events.size() && events[i].axis == axis && events[i].position == position &&
               events[i].type == kStart)
          ++starts, ++i;
        right -= planars + ends;
        // Planes on the cell's boundary cut off nothing.
        if (position > cell.min[axis] && position < cell.max[axis]) {
          Aabb below = cell, above = cell;
          below.max[axis] = position;
          above.min[axis] = position;
          const float p_below = surface(below) / area, p_above = surface(above) / area;
          const auto cost = [&](uint32_t nl, uint32_t nr) {
            const float bonus = (nl == 0 || nr == 0) ? 1.0f - options.empty_bonus : 1.0f;
            return bonus * (options.traversal_cost + options.intersection_cost * (p_below * static_cast<float>(nl) +
                                                                                  p_above * static_cast<float>(nr)));
          };
          const float planar_left_cost = cost(left + planars, right);
          const float planar_right_cost = cost(left, right + planars);
          const bool to_left = planar_left_cost <= planar_right_cost;
          const float c = to_left ? planar_left_cost : planar_right_cost;
          if (c < best.cost) best = {c, axis, position, to_left};
        }
        left += starts + planars;
      }
    }
    return best;
  }

  std::unique_ptr<TempNode> build(NodeInput input, const Aabb& cell, uint32_t level, uint32_t& deepest) {
    auto node = std::make_unique<TempNode>();
    deepest = std::max(deepest, level);
    const auto n = static_cast<uint32_t>(input.prims.size());
    const Plane plane = level < max_depth && n > 0 ? find_plane(input, cell) : Plane{};
    if (plane.axis < 0 || !(plane.cost < options.intersection_cost * static_cast<float>(n))) {
      node->prims = std::move(input.prims);
      std::sort(node->prims.begin(), node->prims.end());
      return node;
    }

    // Classify: 0 both, 1 below only, 2 above only.
    std::vector<uint8_t> side(n, 0);
    for (const Event& event : input.events) {
      if (event.axis != plane.axis) continue;
      if (event.type == kEnd && event.position <= plane.position) side[event.prim] = 1;
      else if (event.type == kStart && event.position >= plane.position) side[event.prim] = 2;
      else if (event.type == kPlanar) {
        if (event.position < plane.position || (event.position == plane.position && plane.planar_left))
          side[event.prim] = 1;
        else
          side[event.prim] = 2;
      }
    }

    Aabb below_cell = cell, above_cell = cell;
    below_cell.max[plane.axis] = plane.position;
    above_cell.min[plane.axis] = plane.position;
    NodeInput below, above;
    std::vector<uint32_t> below_index(n, ~0u), above_index(n, ~0u);
    // Straddling triangles, clipped to each child cell; the new parts' events are sorted apart.
    std::vector<Event> below_new, above_new;
    for (uint32_t i = 0; i < n; ++i) {
      const auto add = [&](NodeInput& child, std::vector<uint32_t>& index, const Aabb& box) {
        index[i] = static_cast<uint32_t>(child.prims.size());
        child.prims.push_back(input.prims[i]);
        child.boxes.push_back(box);
      };
      if (side[i] == 1) add(below, below_index, input.boxes[i]);
      else if (side[i] == 2) add(above, above_index, input.boxes[i]);
      else {
        const Triangle tri = mesh.triangle(input.prims[i]);
        const Aabb in_below = intersect(intersect(clip_triangle(tri, below_cell), input.boxes[i]), below_cell);
        const Aabb in_above = intersect(intersect(clip_triangle(tri, above_cell), input.boxes[i]), above_cell);
        const bool keep_below = !in_below.empty() || in_above.empty();
        if (keep_below) {
          add(below, below_index, in_below.empty() ? intersect(input.boxes[i], below_cell) : in_below);
          add_events(below.boxes.back(), below_index[i], below_new);
        }
        if (!in_above.empty()) {
          add(above, above_index, in_above);
          add_events(in_above, above_index[i], above_new);
        }
      }
    }
    for (const Event& event : input.events) {
      if (side[event.prim] == 1) below.events.push_back({event.position, below_index[event.prim], event.axis, event.type});
      else if (side[event.prim] == 2)
        above.events.push_back({event.position, above_index[event.prim], event.axis, event.type});
    }
    input = NodeInput{};
    const auto merge_new = [](std::vector<Event>& events, std::vector<Event>& fresh) {
      std::sort(fresh.begin(), fresh.end(), event_less);
      const auto middle = static_cast<std::ptrdiff_t>(events.size());
      events.insert(events.end(), fresh.begin(), fresh.end());
      std::inplace_merge(events.begin(), events.begin() + middle, events.end(), event_less);
    };
    merge_new(below.events, below_new);
    merge_new(above.events, above_new);

    node->axis = plane.axis;
    node->split = plane.position;
    uint32_t below_depth = 0, above_depth = 0;
    if (n >= options.parallel_threshold) {
      tbb::task_group group;
      group.run([&] { node->below = build(std::move(below), below_cell, level + 1, below_depth); });
      node->above = build(std::move(above), above_cell, level + 1, above_depth);
      group.wait();
    } else {
      node->below = build(std::move(below), below_cell, level + 1, below_depth);
      node->above = build(std::move(above), above_cell, level + 1, above_depth);
    }
    deepest = std::max({deepest, below_depth, above_depth});
    return node;
  }
};

// Depth first: the below child right after its parent, the above child's index patched in.
void flatten(const TempNode& node, KdTree& tree) {
  const auto index = tree.nodes.size();
  if (index > kMaxKdIndex) fail("accel: build_kdtree: more than 2^30 nodes");
  if (node.axis < 0) {
    if (node.prims.size() > kMaxKdIndex) fail("accel: build_kdtree: a leaf of more than 2^30 triangles");
    tree.nodes.push_back(KdNode::leaf(static_cast<uint32_t>(tree.prim_indices.size()),
                                      static_cast<uint32_t>(node.prims.size())));
    tree.prim_indices.insert(tree.prim_indices.end(), node.prims.begin(), node.prims.end());
    return;
  }
  tree.nodes.push_back(KdNode::interior(node.axis, node.split, 0));
  flatten(*node.below, tree);
  tree.nodes[index] = KdNode::interior(node.axis, node.split, static_cast<uint32_t>(tree.nodes.size()));
  flatten(*node.above, tree);
}

}  // namespace

uint32_t kdtree_depth_limit(uint32_t triangle_count, const KdTreeOptions& options) {
  if (options.max_depth > 0) return std::min(options.max_depth, kMaxKdDepth);
  const double levels = 8.0 + 1.3 * std::log2(std::max(1.0, static_cast<double>(triangle_count)));
  return std::min(static_cast<uint32_t>(std::lround(levels)), kMaxKdDepth);
}

KdTree build_kdtree(const TriangleMesh& mesh, const KdTreeOptions& options) {
  const Stopwatch watch;
  if (mesh.triangle_count > kMaxKdIndex)
    fail("accel: build_kdtree: {} triangles, at most 2^30 - 1", mesh.triangle_count);
  if (!(options.traversal_cost > 0.0f && options.intersection_cost > 0.0f))
    fail("accel: build_kdtree: traversal_cost and intersection_cost must be positive");
  if (!(options.empty_bonus >= 0.0f && options.empty_bonus < 1.0f))
    fail("accel: build_kdtree: empty_bonus must be in [0, 1), got {}", options.empty_bonus);

  KdTree tree;
  tree.prim_count = mesh.triangle_count;
  if (mesh.triangle_count > 0) {
    NodeInput root;
    root.boxes.resize(mesh.triangle_count);
    triangle_boxes(mesh, root.boxes);  // also rejects non-finite vertices
    root.prims.resize(mesh.triangle_count);
    root.events.reserve(6 * size_t{mesh.triangle_count});
    for (uint32_t i = 0; i < mesh.triangle_count; ++i) {
      root.prims[i] = i;
      tree.bounds.extend(root.boxes[i]);
      add_events(root.boxes[i], i, root.events);
    }
    std::sort(root.events.begin(), root.events.end(), event_less);
    Builder builder{mesh, options, kdtree_depth_limit(mesh.triangle_count, options)};
    uint32_t deepest = 0;
    const std::unique_ptr<TempNode> top = builder.build(std::move(root), tree.bounds, 1, deepest);
    flatten(*top, tree);
    tree.depth = deepest;
  }
  tree.build_ms = watch.elapsed_ms();
  return tree;
}

void refit(KdTree& /*tree*/, const TriangleMesh& /*mesh*/) {
  fail("accel: refit: a kd-tree is not refittable (its leaves depend on where triangles cross split planes); "
       "rebuild it instead");
}

}  // namespace glint::accel
