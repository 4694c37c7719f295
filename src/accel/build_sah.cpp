#include "accel/build_sah.h"

#include "accel/primitive_bounds.h"
#include "accel/ray.h"
#include "accel/top_down_builder.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <vector>

namespace glint::accel {
namespace {

struct Bin {
  Aabb box;
  uint32_t count = 0;
};

// bins[axis * bin_count + b]
using Bins = std::vector<Bin>;

// Maps a centroid coordinate to its bin; the same function serves binning and partitioning, so
// both always agree on which side a primitive falls.
struct BinMapping {
  vec3 origin;
  vec3 scale;  // bins per unit length; 0 on an axis whose centroids all coincide
  uint32_t bin_count;

  uint32_t bin(const vec3& centroid, int axis) const {
    const float position = (centroid[axis] - origin[axis]) * scale[axis];
    // Clamped in float before the conversion (converting an out-of-range float is undefined); the
    // largest centroid lands exactly on bin_count and belongs to the last bin.
    if (!(position > 0.0f)) return 0;
    return position < static_cast<float>(bin_count - 1) ? static_cast<uint32_t>(position) : bin_count - 1;
  }
};

Bins fill_bins(const detail::SplitContext& context, const detail::PrimRange& range, const BinMapping& mapping) {
  const auto accumulate = [&](uint32_t from, uint32_t to, Bins bins) {
    for (uint32_t i = from; i != to; ++i) {
      const uint32_t prim = context.prim_indices[i];
      const vec3& centroid = context.input.centroids[prim];
      for (int axis = 0; axis < 3; ++axis) {
        Bin& bin = bins[axis * mapping.bin_count + mapping.bin(centroid, axis)];
        bin.box.extend(context.input.boxes[prim]);
        ++bin.count;
      }
    }
    return bins;
  };
  Bins empty(3 * size_t{mapping.bin_count});
  if (!context.parallel) return accumulate(range.begin, range.end, std::move(empty));
  return tbb::parallel_reduce(
      tbb::blocked_range<uint32_t>(range.begin, range.end, 16384), empty,
      [&](const tbb::blocked_range<uint32_t>& r, Bins bins) { return accumulate(r.begin(), r.end(), std::move(bins)); },
      [](Bins a, const Bins& b) {
        for (size_t i = 0; i < a.size(); ++i) {
          a[i].box.extend(b[i].box);
          a[i].count += b[i].count;
        }
        return a;
      });
}

std::optional<uint32_t> sah_policy(const detail::SplitContext& context, const detail::PrimRange& range) {
  const BuildOptions& options = context.options;
  const uint32_t bin_count = options.bins;
  const vec3 extent = range.centroid_box.extent();
  BinMapping mapping{range.centroid_box.min, vec3(0.0f), bin_count};
  for (int axis = 0; axis < 3; ++axis)
    if (extent[axis] > 0.0f) {
      const float scale = static_cast<float>(bin_count) / extent[axis];
      if (scale < kInfinity) mapping.scale[axis] = scale;  // a subnormal extent is as good as none
    }
  if (mapping.scale == vec3(0.0f)) return std::nullopt;  // all centroids coincide: no SAH split exists

  const Bins bins = fill_bins(context, range, mapping);

  // Sweep right to left for the area and count right of each boundary, then left to right to
  // evaluate A_left * N_left + A_right * N_right at every boundary b (bins [0, b) go left).
  float best_cost = std::numeric_limits<float>::infinity();
  int best_axis = -1;
  uint32_t best_boundary = 0;
  std::vector<float> right_cost(bin_count);
  for (int axis = 0; axis < 3; ++axis) {
    if (mapping.scale[axis] == 0.0f) continue;
    const Bin* axis_bins = bins.data() + axis * bin_count;
    Aabb right;
    uint32_t right_count = 0;
    for (uint32_t b = bin_count - 1; b > 0; --b) {
      right.extend(axis_bins[b].box);
      right_count += axis_bins[b].count;
      right_cost[b] = half_area(right) * static_cast<float>(right_count);
    }
    Aabb left;
    uint32_t left_count = 0;
    for (uint32_t b = 1; b < bin_count; ++b) {
      left.extend(axis_bins[b - 1].box);
      left_count += axis_bins[b - 1].count;
      if (left_count == 0 || left_count == range.size()) continue;
      const float cost = half_area(left) * static_cast<float>(left_count) + right_cost[b];
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_boundary = b;
      }
    }
  }
  if (best_axis < 0) return std::nullopt;

  const float node_area = half_area(range.box);
  const float split_cost = options.traversal_cost +
                           (node_area > 0.0f ? options.intersection_cost * best_cost / node_area
                                             : options.intersection_cost * static_cast<float>(range.size()));
  const float leaf_cost = options.intersection_cost * static_cast<float>(range.size());
  if (range.size() <= options.max_leaf_size && leaf_cost <= split_cost) return std::nullopt;

  const auto first = context.prim_indices.begin();
  const auto middle = std::partition(first + range.begin, first + range.end, [&](uint32_t prim) {
    return mapping.bin(context.input.centroids[prim], best_axis) < best_boundary;
  });
  return static_cast<uint32_t>(middle - first);
}

}  // namespace

Bvh build_sah(const BuildInput& input, const BuildOptions& options) {
  if (options.bins < 2 || options.bins > 256) fail("accel: build_sah: bins must be in [2, 256], got {}", options.bins);
  return detail::build_top_down(input, options, "sah", sah_policy);
}

}  // namespace glint::accel
