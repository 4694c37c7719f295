#pragma once
// Internal to build_sah: binned SAH split finding (Wald 2007). A range's centroids are binned into
// bin_count slabs per axis; every bin keeps the box and count of what fell in it; a sweep over the
// bin boundaries of each axis finds the cheapest split. Large ranges are binned in parallel: chunks
// fill their own bins, which are merged. Merging takes minima, maxima and sums, which are exact, so
// parallel binning gives exactly the bins serial binning gives, whatever the number of threads.
#include "accel/builders/prim_ref.h"

#include <xmmintrin.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace glint::accel::detail {

inline constexpr uint32_t kMaxSahBins = 256;

// Maps a centroid coordinate to its bin; the same function serves binning and partitioning, so both
// always agree on which side a primitive falls.
struct BinMapping {
  vec3 origin{0.0f};
  vec3 scale{0.0f};  // bins per unit length; 0 on an axis whose centroids all coincide
  uint32_t bin_count = 0;

  uint32_t bin(const vec3& centroid, int axis) const {
    const float position = (centroid[axis] - origin[axis]) * scale[axis];
    // Clamped in float before the conversion (converting an out-of-range float is undefined): max
    // with 0 sends NaN and everything not above 0 to bin 0 (_mm_max_ss(a, b) is a > b ? a : b), min
    // sends the largest centroid, which lands exactly on bin_count, to the last bin. Branch-free:
    // partitions call this once per reference and the branches mispredicted.
    const __m128 clamped = _mm_min_ss(_mm_max_ss(_mm_set_ss(position), _mm_setzero_ps()),
                                      _mm_set_ss(static_cast<float>(bin_count - 1)));
    return static_cast<uint32_t>(_mm_cvttss_si32(clamped));
  }
};

// The mapping over a range's centroid bounds, or nullopt when all centroids coincide (no axis to
// split along). bin_count in [2, kMaxSahBins].
std::optional<BinMapping> bin_mapping(const Aabb& centroid_box, uint32_t bin_count);

// Fixed capacity, so binning a node allocates nothing; only the first 3 * bin_count bins are
// initialised (clear) and used, bin (axis, b) at index axis * bin_count + b. A bin's box is two
// 4-float rows (the fourth lane unused), so one SSE min and one max update it (unaligned loads: a
// TBB-allocated copy need not keep the 16-byte alignment).
struct SahBins {
  uint32_t bin_count = 0;
  alignas(16) std::array<std::array<float, 4>, 3 * kMaxSahBins> box_min;
  alignas(16) std::array<std::array<float, 4>, 3 * kMaxSahBins> box_max;
  std::array<uint32_t, 3 * kMaxSahBins> counts;

  void clear(uint32_t count);
  uint32_t index(int axis, uint32_t b) const { return static_cast<uint32_t>(axis) * bin_count + b; }
  uint32_t count(int axis, uint32_t b) const { return counts[index(axis, b)]; }
  Aabb box(int axis, uint32_t b) const {
    const auto& lo = box_min[index(axis, b)];
    const auto& hi = box_max[index(axis, b)];
    return {vec3(lo[0], lo[1], lo[2]), vec3(hi[0], hi[1], hi[2])};
  }
  void add(const SahBins& other);  // bin-wise union of boxes, sum of counts
  // Same bin count, and every used bin has the same count and (when not empty) the same box.
  bool operator==(const SahBins& other) const;
};

// Bins refs[range.begin, range.end) along all three axes into `bins` (cleared first). With
// `parallel`, chunks of `chunk` references are binned by TBB tasks and merged.
void bin_refs(std::span<const PrimRef> refs, const PrimRange& range, const BinMapping& mapping, bool parallel,
              uint32_t chunk, SahBins& bins);

// How many references of each block of a range fell in each bin: block b is references
// [range.begin + b * chunk, ...) and its counts are 3 * bin_count numbers laid out like SahBins's.
// Binning records them so that a parallel partition of the same blocks by a bin boundary knows
// every block's left count without a counting pass over the references.
class BlockBinCounts {
 public:
  void reset(uint32_t blocks, uint32_t slots) {
    blocks_ = blocks;
    slots_ = slots;
    counts_.resize(size_t{blocks} * slots);
  }
  uint32_t blocks() const { return blocks_; }
  uint32_t* block(uint32_t b) { return counts_.data() + size_t{b} * slots_; }
  const uint32_t* block(uint32_t b) const { return counts_.data() + size_t{b} * slots_; }
  // out[b] = references of block b in bins [0, boundary) of `axis` (out.size() >= blocks()).
  void left_counts(int axis, uint32_t boundary, uint32_t bin_count, std::span<uint32_t> out) const;

 private:
  uint32_t blocks_ = 0;
  uint32_t slots_ = 0;
  std::vector<uint32_t> counts_;
};

// bin_refs in parallel over the blocks of `chunk` references, also recording every block's counts.
void bin_refs_by_block(std::span<const PrimRef> refs, const PrimRange& range, const BinMapping& mapping,
                       uint32_t chunk, SahBins& bins, BlockBinCounts& block_counts);

// The cheapest boundary: bins [0, boundary) of `axis` go left. cost = A_left N_left + A_right N_right
// with A the half surface area (not yet divided by the node's area).
struct SahSplit {
  int axis = -1;
  uint32_t boundary = 0;
  float cost = 0.0f;
};

// nullopt when no boundary of a non-flat axis has primitives on both sides.
std::optional<SahSplit> best_sah_split(const SahBins& bins, const BinMapping& mapping, uint32_t count);

// Ranges of at most this many references are the majority of nodes; for them clearing, filling and
// sweeping 3 x bin_count bins costs more than looking at the references themselves.
inline constexpr uint32_t kSmallSahRange = 8;

// The same split as binning refs[range] and best_sah_split, found without bins (range.size() <=
// kSmallSahRange): per axis, the references sorted by bin index, each group of equal bins taking the
// place of its bin. Both sides' boxes are the same unions of the same boxes and the costs the same
// expressions, so axis, boundary and cost are bit for bit those of best_sah_split.
std::optional<SahSplit> best_sah_split_small(std::span<const PrimRef> refs, const PrimRange& range,
                                             const BinMapping& mapping);

}  // namespace glint::accel::detail
