#include "accel/builders/build_sbvh.h"

#include "accel/builders/primitive_bounds.h"
#include "accel/ray.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace glint::accel {
namespace {

// A primitive, or the part of it inside the slabs its ancestors' spatial splits kept.
struct Reference {
  Aabb box;
  uint32_t prim = 0;
};

using References = std::vector<Reference>;

Aabb intersect(const Aabb& a, const Aabb& b) { return Aabb{glm::max(a.min, b.min), glm::min(a.max, b.max)}; }

// A float box around a point computed in double, grown by about two ulps (at least the smallest
// normal float) so it contains the exact point whatever the rounding: clipped boxes stay
// conservative, and a ray that hits the triangle always enters the box of the part it hits.
// (Cheaper than rounding each coordinate outward with nextafter, which dominated the build.)
void extend_outward(Aabb& box, const glm::dvec3& p) {
  const vec3 value(p);
  const vec3 slack = glm::abs(value) * 0x1p-22f + vec3(std::numeric_limits<float>::min());
  box.min = glm::min(box.min, value - slack);
  box.max = glm::max(box.max, value + slack);
}

// Splits `ref` at the plane x[axis] = position into the boxes of its parts on each side (either may
// come out empty when the triangle does not actually reach that side). With a mesh the triangle's
// edges are clipped (the paper's split); without one the box is cut.
void split_reference(const TriangleMesh* mesh, const Reference& ref, int axis, float position, Aabb& left,
                     Aabb& right) {
  left = Aabb{};
  right = Aabb{};
  if (mesh == nullptr) {
    left = ref.box;
    right = ref.box;
  } else {
    const Triangle tri = mesh->triangle(ref.prim);
    const vec3 corners[3] = {tri.v0, tri.v1, tri.v2};
    for (int i = 0; i < 3; ++i) {
      const vec3& a = corners[i];
      const vec3& b = corners[(i + 1) % 3];
      if (a[axis] <= position) left.extend(a);
      if (a[axis] >= position) right.extend(a);
      if ((a[axis] < position && b[axis] > position) || (a[axis] > position && b[axis] < position)) {
        const glm::dvec3 da(a), db(b);
        const double t = (static_cast<double>(position) - da[axis]) / (db[axis] - da[axis]);
        glm::dvec3 crossing = da + (db - da) * t;
        crossing[axis] = position;
        extend_outward(left, crossing);
        extend_outward(right, crossing);
      }
    }
  }
  left.max[axis] = std::min(left.max[axis], position);
  right.min[axis] = std::max(right.min[axis], position);
  left = intersect(left, ref.box);
  right = intersect(right, ref.box);
}

// Maps a coordinate to one of `count` equal slabs of [origin, origin + count / scale].
struct BinMapping {
  float origin = 0.0f;
  float scale = 0.0f;
  uint32_t count = 0;

  uint32_t bin(float x) const {
    const float position = (x - origin) * scale;
    if (!(position > 0.0f)) return 0;
    return position < static_cast<float>(count - 1) ? static_cast<uint32_t>(position) : count - 1;
  }
  float boundary(uint32_t b) const { return origin + static_cast<float>(b) / scale; }
};

// Returns the mapping for `extent` along one axis, or count == 0 when the extent is too small.
BinMapping make_mapping(float min, float extent, uint32_t count) {
  if (!(extent > 0.0f)) return {};
  const float scale = static_cast<float>(count) / extent;
  if (!(scale < kInfinity)) return {};
  return {min, scale, count};
}

struct Bin {
  Aabb box;
  uint32_t entries = 0;  // object bins: the references; spatial bins: those starting here
  uint32_t exits = 0;    // spatial bins: references ending here
};

// Bins of all three axes in one array, reduced in parallel on large nodes.
template <typename Fill>
std::vector<Bin> fill_bins(const References& refs, uint32_t bin_count, bool parallel, Fill fill) {
  std::vector<Bin> empty(3 * size_t{bin_count});
  const auto accumulate = [&](size_t from, size_t to, std::vector<Bin> bins) {
    for (size_t i = from; i != to; ++i) fill(refs[i], bins);
    return bins;
  };
  if (!parallel) return accumulate(0, refs.size(), std::move(empty));
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, refs.size(), 4096), empty,
      [&](const tbb::blocked_range<size_t>& r, std::vector<Bin> bins) {
        return accumulate(r.begin(), r.end(), std::move(bins));
      },
      [](std::vector<Bin> a, const std::vector<Bin>& b) {
        for (size_t i = 0; i < a.size(); ++i) {
          a[i].box.extend(b[i].box);
          a[i].entries += b[i].entries;
          a[i].exits += b[i].exits;
        }
        return a;
      });
}

// The best boundary of one kind of split: cost = A(left) N(left) + A(right) N(right).
struct SplitChoice {
  float cost = std::numeric_limits<float>::infinity();
  int axis = -1;
  uint32_t boundary = 0;
  Aabb left, right;
  uint32_t left_count = 0, right_count = 0;
  BinMapping mapping;

  bool valid() const { return axis >= 0; }
};

// Sweeps the bins of every axis. Object bins count each reference once; spatial bins count a
// reference on the left where it starts and on the right where it ends (straddlers on both sides).
template <bool kSpatial>
void sweep(const std::vector<Bin>& bins, const BinMapping (&mappings)[3], SplitChoice& best) {
  for (int axis = 0; axis < 3; ++axis) {
    const BinMapping& mapping = mappings[axis];
    if (mapping.count == 0) continue;
    const Bin* axis_bins = bins.data() + size_t(axis) * mapping.count;
    std::vector<Aabb> right_box(mapping.count);
    std::vector<uint32_t> right_count(mapping.count);
    Aabb right;
    uint32_t count = 0;
    for (uint32_t b = mapping.count - 1; b > 0; --b) {
      right.extend(axis_bins[b].box);
      count += kSpatial ? axis_bins[b].exits : axis_bins[b].entries;
      right_box[b] = right;
      right_count[b] = count;
    }
    Aabb left;
    uint32_t left_count = 0;
    for (uint32_t b = 1; b < mapping.count; ++b) {
      left.extend(axis_bins[b - 1].box);
      left_count += axis_bins[b - 1].entries;
      if (left_count == 0 || right_count[b] == 0) continue;
      const float cost = half_area(left) * static_cast<float>(left_count) +
                         half_area(right_box[b]) * static_cast<float>(right_count[b]);
      if (cost < best.cost) best = {cost, axis, b, left, right_box[b], left_count, right_count[b], mapping};
    }
  }
}

// Levels an object-median split needs below `count` references (see top_down_builder.cpp): checked
// at every split so no choice can push the tree past kMaxBvhDepth.
uint32_t median_levels(size_t count, uint32_t max_leaf_size) {
  uint32_t levels = 0;
  while (count > max_leaf_size) {
    count -= count / 2;
    ++levels;
  }
  return levels;
}

struct Builder {
  const TriangleMesh* mesh;  // null: box clipping
  const BuildOptions& options;
  const SbvhOptions& sbvh;
  float root_area = 0.0f;
  std::vector<BvhNode>& nodes;
  std::vector<uint32_t>& prim_indices;
  std::atomic<uint32_t> next_node{1};
  std::atomic<uint32_t> next_slot{0};
  std::atomic<uint32_t> depth{0};

  SplitChoice object_split(const References& refs, bool parallel) const {
    Aabb centroids;
    for (const Reference& ref : refs) centroids.extend(ref.box.center());
    BinMapping mappings[3];
    const vec3 extent = centroids.extent();
    for (int axis = 0; axis < 3; ++axis) mappings[axis] = make_mapping(centroids.min[axis], extent[axis], options.bins);
    SplitChoice best;
    if (mappings[0].count + mappings[1].count + mappings[2].count == 0) return best;
    const std::vector<Bin> bins = fill_bins(refs, options.bins, parallel, [&](const Reference& ref, std::vector<Bin>& b) {
      const vec3 c = ref.box.center();
      for (int axis = 0; axis < 3; ++axis) {
        if (mappings[axis].count == 0) continue;
        Bin& bin = b[size_t(axis) * options.bins + mappings[axis].bin(c[axis])];
        bin.box.extend(ref.box);
        ++bin.entries;
      }
    });
    sweep<false>(bins, mappings, best);
    return best;
  }

  SplitChoice spatial_split(const References& refs, const Aabb& box, bool parallel) const {
    const uint32_t count = sbvh.spatial_bins;
    BinMapping mappings[3];
    const vec3 extent = box.extent();
    for (int axis = 0; axis < 3; ++axis) mappings[axis] = make_mapping(box.min[axis], extent[axis], count);
    SplitChoice best;
    if (mappings[0].count + mappings[1].count + mappings[2].count == 0) return best;
    const std::vector<Bin> bins = fill_bins(refs, count, parallel, [&](const Reference& ref, std::vector<Bin>& b) {
      for (int axis = 0; axis < 3; ++axis) {
        const BinMapping& mapping = mappings[axis];
        if (mapping.count == 0) continue;
        Bin* axis_bins = b.data() + size_t(axis) * count;
        const uint32_t first = mapping.bin(ref.box.min[axis]);
        const uint32_t last = mapping.bin(ref.box.max[axis]);
        // Chopped binning: cut the reference at each slab boundary it crosses, left to right.
        Reference rest = ref;
        for (uint32_t bin = first; bin < last; ++bin) {
          Aabb left, right;
          split_reference(mesh, rest, axis, mapping.boundary(bin + 1), left, right);
          axis_bins[bin].box.extend(left);
          rest.box = right;
          if (rest.box.empty()) break;
        }
        if (!rest.box.empty()) axis_bins[last].box.extend(rest.box);
        ++axis_bins[first].entries;
        ++axis_bins[last].exits;
      }
    });
    sweep<true>(bins, mappings, best);
    return best;
  }

  // Sorts by centroid on the widest axis and halves; always succeeds for two or more references.
  static size_t median_split(References& refs) {
    Aabb centroids;
    for (const Reference& ref : refs) centroids.extend(ref.box.center());
    const vec3 e = centroids.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const size_t mid = refs.size() / 2;
    std::nth_element(refs.begin(), refs.begin() + static_cast<std::ptrdiff_t>(mid), refs.end(),
                     [axis](const Reference& a, const Reference& b) {
                       const float ca = a.box.min[axis] + a.box.max[axis], cb = b.box.min[axis] + b.box.max[axis];
                       return ca < cb || (ca == cb && a.prim < b.prim);
                     });
    return mid;
  }

  // Distributes the references of a spatial split; straddlers are split or, when cheaper, sent
  // whole to one side (reference unsplitting). Returns false when it would spend more than
  // `budget` extra references or leave a side empty.
  bool apply_spatial(const References& refs, const SplitChoice& split, uint64_t budget, References& left,
                     References& right) const {
    const int axis = split.axis;
    const float position = split.mapping.boundary(split.boundary);
    Aabb left_box = split.left, right_box = split.right;
    auto left_count = static_cast<float>(split.left_count), right_count = static_cast<float>(split.right_count);
    uint64_t duplicates = 0;
    for (const Reference& ref : refs) {
      const uint32_t first = split.mapping.bin(ref.box.min[axis]);
      const uint32_t last = split.mapping.bin(ref.box.max[axis]);
      if (last < split.boundary) {
        left.push_back(ref);
        continue;
      }
      if (first >= split.boundary) {
        right.push_back(ref);
        continue;
      }
      Aabb to_left = left_box, to_right = right_box;
      to_left.extend(ref.box);
      to_right.extend(ref.box);
      const float split_cost = half_area(left_box) * left_count + half_area(right_box) * right_count;
      const float left_cost = half_area(to_left) * left_count + half_area(right_box) * (right_count - 1.0f);
      const float right_cost = half_area(left_box) * (left_count - 1.0f) + half_area(to_right) * right_count;
      Aabb left_part, right_part;
      split_reference(mesh, ref, axis, position, left_part, right_part);
      // The triangle may not reach one side although its box does: the tighter part alone.
      if (left_part.empty() || right_part.empty()) {
        const bool to_right_side = left_part.empty() && !right_part.empty();
        (to_right_side ? right : left).push_back(left_part.empty() && right_part.empty() ? ref
                                                  : Reference{to_right_side ? right_part : left_part, ref.prim});
        (to_right_side ? left_count : right_count) -= 1.0f;
        continue;
      }
      if (left_cost < split_cost && left_cost <= right_cost) {  // unsplit: whole reference left
        left.push_back(ref);
        left_box = to_left;
        right_count -= 1.0f;
      } else if (right_cost < split_cost) {  // unsplit: whole reference right
        right.push_back(ref);
        right_box = to_right;
        left_count -= 1.0f;
      } else {
        left.push_back(Reference{left_part, ref.prim});
        right.push_back(Reference{right_part, ref.prim});
        ++duplicates;
      }
    }
    return duplicates <= budget && !left.empty() && !right.empty();
  }

  static float partition_cost(const References& refs) {
    Aabb box;
    for (const Reference& ref : refs) box.extend(ref.box);
    return half_area(box) * static_cast<float>(refs.size());
  }

  void object_partition(const References& refs, const SplitChoice& split, References& left, References& right) const {
    for (const Reference& ref : refs)
      (split.mapping.bin(ref.box.center()[split.axis]) < split.boundary ? left : right).push_back(ref);
  }

  void make_leaf(BvhNode& node, const References& refs) {
    const uint32_t first = next_slot.fetch_add(static_cast<uint32_t>(refs.size()), std::memory_order_relaxed);
    for (size_t i = 0; i < refs.size(); ++i) prim_indices[first + i] = refs[i].prim;
    node.first = first;
    node.prim_count = static_cast<uint32_t>(refs.size());
  }

  void build(uint32_t node_index, References refs, uint32_t level, uint64_t budget) {
    BvhNode& node = nodes[node_index];
    Aabb box;
    for (const Reference& ref : refs) box.extend(ref.box);
    node.set_bounds(box);
    uint32_t seen = depth.load(std::memory_order_relaxed);
    while (level > seen && !depth.compare_exchange_weak(seen, level, std::memory_order_relaxed)) {
    }
    const size_t count = refs.size();
    if (count == 1) return make_leaf(node, refs);
    const bool parallel = count >= options.parallel_threshold;

    const SplitChoice object = object_split(refs, parallel);
    SplitChoice spatial;
    const float overlap = object.valid() ? half_area(intersect(object.left, object.right)) : kInfinity;
    if (budget > 0 && overlap > sbvh.alpha * root_area) spatial = spatial_split(refs, box, parallel);

    const bool use_spatial = spatial.valid() && spatial.cost < object.cost;
    const float area = half_area(box);
    const float leaf_cost = options.intersection_cost * static_cast<float>(count);
    const auto cost_of_split = [&](float sah) {
      return options.traversal_cost + (area > 0.0f ? options.intersection_cost * sah / area : leaf_cost);
    };
    const bool fits_leaf = count <= options.max_leaf_size;
    const float estimate = use_spatial ? spatial.cost : object.cost;
    if (fits_leaf && (!std::isfinite(estimate) || leaf_cost <= cost_of_split(estimate))) return make_leaf(node, refs);

    References left, right;
    uint64_t spent = 0;
    bool done = false;
    float actual = object.cost;  // exact for an object split: the bins' boxes are the children's
    if (use_spatial) {
      done = apply_spatial(refs, spatial, budget, left, right);
      // The binned estimate assumed every straddler split; unsplitting and clipping change the
      // real children, so keep the spatial split only if it really beats the object split.
      if (done) actual = partition_cost(left) + partition_cost(right);
      if (done && object.valid()) done = actual < object.cost;
      if (done) spent = left.size() + right.size() - count;
    }
    if (!done && object.valid()) {
      left.clear();
      right.clear();
      object_partition(refs, object, left, right);
      done = !left.empty() && !right.empty();
      actual = object.cost;
    }
    // The split actually made may cost more than the estimate that ruled out a leaf.
    if (fits_leaf && (!done || leaf_cost <= cost_of_split(actual))) return make_leaf(node, refs);
    const auto fits_depth = [&](size_t child) {
      return level + 1 + median_levels(child, options.max_leaf_size) <= kMaxBvhDepth;
    };
    if (!done || !fits_depth(left.size()) || !fits_depth(right.size())) {
      if (fits_leaf) return make_leaf(node, refs);
      const size_t mid = median_split(refs);
      left.assign(refs.begin(), refs.begin() + static_cast<std::ptrdiff_t>(mid));
      right.assign(refs.begin() + static_cast<std::ptrdiff_t>(mid), refs.end());
      spent = 0;
    }
    refs = References{};

    // Unspent extra references go to the children in proportion to their sizes.
    const uint64_t rest = budget - spent;
    const uint64_t left_budget = rest * left.size() / (left.size() + right.size());
    const uint32_t first = next_node.fetch_add(2, std::memory_order_relaxed);
    node.first = first;
    node.prim_count = 0;
    if (parallel) {
      tbb::task_group group;
      group.run([&] { build(first, std::move(left), level + 1, left_budget); });
      build(first + 1, std::move(right), level + 1, rest - left_budget);
      group.wait();
    } else {
      build(first, std::move(left), level + 1, left_budget);
      build(first + 1, std::move(right), level + 1, rest - left_budget);
    }
  }
};

// Renumbers nodes depth-first and lays the leaves' slots out in the same order, so the arrays do
// not depend on the order in which TBB tasks grabbed node indices and slots.
void depth_first_order(const std::vector<BvhNode>& nodes, const std::vector<uint32_t>& slots, Bvh& bvh) {
  bvh.nodes.clear();
  bvh.nodes.push_back(nodes[0]);
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    BvhNode& node = bvh.nodes[index];
    if (node.is_leaf()) {
      const auto first = static_cast<uint32_t>(bvh.prim_indices.size());
      for (uint32_t s = node.first; s != node.first + node.prim_count; ++s) bvh.prim_indices.push_back(slots[s]);
      node.first = first;
      continue;
    }
    const uint32_t old_left = node.left();
    const auto new_left = static_cast<uint32_t>(bvh.nodes.size());
    bvh.nodes[index].first = new_left;
    bvh.nodes.push_back(nodes[old_left]);
    bvh.nodes.push_back(nodes[old_left + 1]);
    stack.push_back(new_left + 1);
    stack.push_back(new_left);
  }
}

Bvh build(const BuildInput& input, const TriangleMesh* mesh, const BuildOptions& options, const SbvhOptions& sbvh) {
  if (input.boxes.size() != input.centroids.size())
    fail("accel: build_sbvh: {} boxes but {} centroids", input.boxes.size(), input.centroids.size());
  if (input.boxes.size() >= (size_t{1} << 30))
    fail("accel: build_sbvh: {} primitives, at most 2^30 - 1", input.boxes.size());
  if (options.max_leaf_size < 1) fail("accel: build_sbvh: max_leaf_size must be at least 1");
  if (options.bins < 2 || options.bins > 256) fail("accel: build_sbvh: bins must be in [2, 256], got {}", options.bins);
  if (sbvh.spatial_bins < 2 || sbvh.spatial_bins > 256)
    fail("accel: build_sbvh: spatial_bins must be in [2, 256], got {}", sbvh.spatial_bins);
  if (!(sbvh.reference_budget >= 1.0f && sbvh.reference_budget <= 64.0f))
    fail("accel: build_sbvh: reference_budget must be in [1, 64], got {}", sbvh.reference_budget);
  if (!(sbvh.alpha >= 0.0f && sbvh.alpha <= 1.0f)) fail("accel: build_sbvh: alpha must be in [0, 1], got {}", sbvh.alpha);

  Bvh bvh;
  bvh.builder = "sbvh";
  bvh.refittable = false;
  const size_t count = input.boxes.size();
  if (count > 0) {
    const auto max_refs = static_cast<size_t>(std::floor(static_cast<double>(sbvh.reference_budget) * double(count)));
    // Every leaf holds at least one reference: at most max_refs leaves, 2 max_refs - 1 nodes.
    std::vector<BvhNode> nodes(2 * max_refs - 1);
    std::vector<uint32_t> slots(max_refs);
    References refs(count);
    for (size_t i = 0; i < count; ++i) refs[i] = Reference{input.boxes[i], static_cast<uint32_t>(i)};
    Builder builder{mesh, options, sbvh, 0.0f, nodes, slots};
    Aabb root;
    for (const Aabb& box : input.boxes) root.extend(box);
    builder.root_area = half_area(root);
    builder.build(0, std::move(refs), 1, max_refs - count);
    nodes.resize(builder.next_node.load());
    slots.resize(builder.next_slot.load());
    bvh.prim_indices.reserve(slots.size());
    depth_first_order(nodes, slots, bvh);
    bvh.depth = builder.depth.load();
  }
  return bvh;
}

}  // namespace

Bvh build_sbvh(const TriangleMesh& mesh, const BuildOptions& options, const SbvhOptions& sbvh) {
  const PrimitiveBounds bounds = triangle_bounds(mesh);
  return build(bounds.input(), &mesh, options, sbvh);
}

Bvh build_sbvh(const BuildInput& input, const BuildOptions& options, const SbvhOptions& sbvh) {
  return build(input, nullptr, options, sbvh);
}

void validate_sbvh_references(const Bvh& bvh, const TriangleMesh& mesh, float reference_budget) {
  const size_t count = mesh.triangle_count;
  if (reference_budget > 0.0f) {
    const auto limit = static_cast<size_t>(std::ceil(static_cast<double>(reference_budget) * double(count)));
    if (bvh.prim_indices.size() > limit)
      fail("sbvh: {} references for {} triangles, over the budget of {}", bvh.prim_indices.size(), count, limit);
  }
  // Boxes of the leaves referencing each triangle.
  std::vector<std::vector<Aabb>> leaf_boxes(count);
  for (const BvhNode& node : bvh.nodes) {
    if (!node.is_leaf()) continue;
    for (uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot) {
      const uint32_t prim = bvh.prim_indices[slot];
      if (prim >= count) fail("sbvh: slot {} references triangle {} of {}", slot, prim, count);
      leaf_boxes[prim].push_back(node.bounds());
    }
  }
  for (uint32_t prim = 0; prim < count; ++prim) {
    const Triangle tri = mesh.triangle(prim);
    const vec3 points[] = {tri.v0, tri.v1, tri.v2, 0.5f * (tri.v0 + tri.v1), 0.5f * (tri.v1 + tri.v2),
                           0.5f * (tri.v2 + tri.v0), (tri.v0 + tri.v1 + tri.v2) / 3.0f};
    for (const vec3& point : points) {
      // The sample points are rounded; a few ulps of slack keep the check about coverage.
      const bool covered = std::any_of(leaf_boxes[prim].begin(), leaf_boxes[prim].end(), [&](const Aabb& box) {
        const vec3 slack = 4e-7f * (glm::abs(box.min) + glm::abs(box.max)) + vec3(1e-30f);
        return Aabb{box.min - slack, box.max + slack}.contains(point);
      });
      if (!covered)
        fail("sbvh: point ({}, {}, {}) of triangle {} is in none of its {} leaves", point.x, point.y, point.z, prim,
             leaf_boxes[prim].size());
    }
  }
}

}  // namespace glint::accel
