#include "accel/sah_binning.h"

#include "accel/primitive_bounds.h"
#include "accel/ray.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <limits>

namespace glint::accel::detail {
namespace {

void bin_serial(std::span<const PrimRef> refs, uint32_t begin, uint32_t end, const BinMapping& shared_mapping,
                SahBins& bins) {
  // Local copies: the stores into the bins cannot alias them, so they stay in registers.
  const BinMapping mapping = shared_mapping;
  const uint32_t bin_count = mapping.bin_count;
  std::array<SahBin*, 3> axis_bins{&bins.bins[0], &bins.bins[bin_count], &bins.bins[2 * size_t{bin_count}]};
  for (uint32_t i = begin; i != end; ++i) {
    const PrimRef& ref = refs[i];
    for (int axis = 0; axis < 3; ++axis) {
      SahBin& bin = axis_bins[static_cast<size_t>(axis)][mapping.bin(ref.centroid, axis)];
      bin.box_min = glm::min(bin.box_min, ref.box_min);
      bin.box_max = glm::max(bin.box_max, ref.box_max);
      ++bin.count;
    }
  }
}

// tbb::parallel_reduce body: a body is split off only when a thread steals work, so bins are
// cleared and merged once per stolen range, not once per chunk. The first body bins straight into
// the caller's bins (no 21 KB copy at the end); split-off bodies bin into their own.
struct BinReduction {
  std::span<const PrimRef> refs;
  const BinMapping& mapping;
  SahBins own;
  SahBins* bins;

  BinReduction(std::span<const PrimRef> r, const BinMapping& m, SahBins& out) : refs(r), mapping(m), bins(&out) {
    bins->clear(m.bin_count);
  }
  BinReduction(BinReduction& other, tbb::split) : refs(other.refs), mapping(other.mapping), bins(&own) {
    own.clear(mapping.bin_count);
  }
  BinReduction(const BinReduction&) = delete;
  BinReduction& operator=(const BinReduction&) = delete;
  void operator()(const tbb::blocked_range<uint32_t>& r) { bin_serial(refs, r.begin(), r.end(), mapping, *bins); }
  void join(const BinReduction& other) { bins->add(*other.bins); }
};

}  // namespace

std::optional<BinMapping> bin_mapping(const Aabb& centroid_box, uint32_t bin_count) {
  const vec3 extent = centroid_box.extent();
  BinMapping mapping{centroid_box.min, vec3(0.0f), bin_count};
  for (int axis = 0; axis < 3; ++axis)
    if (extent[axis] > 0.0f) {
      const float scale = static_cast<float>(bin_count) / extent[axis];
      if (scale < kInfinity) mapping.scale[axis] = scale;  // a subnormal extent is as good as none
    }
  if (mapping.scale == vec3(0.0f)) return std::nullopt;
  return mapping;
}

void SahBins::clear(uint32_t count) {
  bin_count = count;
  for (uint32_t i = 0; i < 3 * count; ++i)
    bins[i] = SahBin{vec3(std::numeric_limits<float>::infinity()), 0, vec3(-std::numeric_limits<float>::infinity())};
}

void SahBins::add(const SahBins& other) {
  for (uint32_t i = 0; i < 3 * bin_count; ++i) {
    bins[i].box_min = glm::min(bins[i].box_min, other.bins[i].box_min);
    bins[i].box_max = glm::max(bins[i].box_max, other.bins[i].box_max);
    bins[i].count += other.bins[i].count;
  }
}

bool SahBins::operator==(const SahBins& other) const {
  if (bin_count != other.bin_count) return false;
  for (uint32_t i = 0; i < 3 * bin_count; ++i)
    if (bins[i].count != other.bins[i].count || bins[i].box_min != other.bins[i].box_min ||
        bins[i].box_max != other.bins[i].box_max)
      return false;
  return true;
}

void bin_refs(std::span<const PrimRef> refs, const PrimRange& range, const BinMapping& mapping, bool parallel,
              uint32_t chunk, SahBins& bins) {
  if (!parallel || range.size() <= chunk) {
    bins.clear(mapping.bin_count);
    bin_serial(refs, range.begin, range.end, mapping, bins);
    return;
  }
  BinReduction reduction(refs, mapping, bins);
  tbb::parallel_reduce(tbb::blocked_range<uint32_t>(range.begin, range.end, chunk), reduction);
}

std::optional<SahSplit> best_sah_split(const SahBins& bins, const BinMapping& mapping, uint32_t count) {
  // Sweep right to left for the area and count right of each boundary, then left to right to
  // evaluate A_left * N_left + A_right * N_right at every boundary b (bins [0, b) go left).
  // An empty bin changes neither side, so its box is not merged and, on the left sweep, a boundary
  // right after it is skipped: it splits the primitives exactly as the boundary before it, at the
  // same cost, and the earlier boundary wins ties anyway. Small nodes, with most bins empty, are
  // the majority, and this skips most of their sweep without changing any result.
  const uint32_t bin_count = mapping.bin_count;
  std::array<float, kMaxSahBins> right_cost;
  std::optional<SahSplit> best;
  float best_cost = std::numeric_limits<float>::infinity();  // an infinite or NaN cost never wins
  for (int axis = 0; axis < 3; ++axis) {
    if (mapping.scale[axis] == 0.0f) continue;
    Aabb right;
    uint32_t right_count = 0;
    float cost_right = 0.0f;
    for (uint32_t b = bin_count - 1; b > 0; --b) {
      const SahBin& bin = bins.at(axis, b);
      if (bin.count != 0) {
        right.extend(Aabb{bin.box_min, bin.box_max});
        right_count += bin.count;
        cost_right = half_area(right) * static_cast<float>(right_count);
      }
      right_cost[b] = cost_right;
    }
    Aabb left;
    uint32_t left_count = 0;
    for (uint32_t b = 1; b < bin_count; ++b) {
      const SahBin& bin = bins.at(axis, b - 1);
      if (bin.count == 0) continue;
      left.extend(Aabb{bin.box_min, bin.box_max});
      left_count += bin.count;
      if (left_count == count) break;  // everything is left from here on
      const float cost = half_area(left) * static_cast<float>(left_count) + right_cost[b];
      if (cost < best_cost) {
        best_cost = cost;
        best = SahSplit{axis, b, cost};
      }
    }
  }
  return best;
}

std::optional<SahSplit> best_sah_split_small(std::span<const PrimRef> refs, const PrimRange& range,
                                             const BinMapping& mapping) {
  const uint32_t count = range.size();
  std::array<uint32_t, kSmallSahRange> bin_of;      // bin of references[i] on the current axis
  std::array<uint32_t, kSmallSahRange> order;       // reference indices sorted by bin
  std::array<float, kSmallSahRange> right_cost_at;  // cost of order[i..] when order[i] starts a bin
  std::optional<SahSplit> best;
  float best_cost = std::numeric_limits<float>::infinity();
  const PrimRef* first = refs.data() + range.begin;
  for (int axis = 0; axis < 3; ++axis) {
    if (mapping.scale[axis] == 0.0f) continue;
    for (uint32_t i = 0; i < count; ++i) {
      bin_of[i] = mapping.bin(first[i].centroid, axis);
      order[i] = i;
      for (uint32_t j = i; j > 0 && bin_of[order[j - 1]] > bin_of[order[j]]; --j) std::swap(order[j - 1], order[j]);
    }
    Aabb right;
    for (uint32_t i = count; i-- > 0;) {
      right.extend(first[order[i]].box());
      if (i == 0 || bin_of[order[i - 1]] != bin_of[order[i]])
        right_cost_at[i] = half_area(right) * static_cast<float>(count - i);
    }
    Aabb left;
    for (uint32_t i = 0; i + 1 < count; ++i) {
      left.extend(first[order[i]].box());
      const uint32_t bin = bin_of[order[i]];
      if (bin == bin_of[order[i + 1]]) continue;  // not the last reference of its bin
      const float cost = half_area(left) * static_cast<float>(i + 1) + right_cost_at[i + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best = SahSplit{axis, bin + 1, cost};
      }
    }
  }
  return best;
}

}  // namespace glint::accel::detail
