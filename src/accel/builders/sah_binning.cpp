#include "accel/builders/sah_binning.h"

#include "accel/builders/primitive_bounds.h"
#include "accel/ray.h"
#include "accel/builders/sse_box.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <emmintrin.h>

#include <algorithm>
#include <limits>

namespace glint::accel::detail {
namespace {

// Per reference: the three bin indices in one SSE computation, then per axis one min and one max on
// the bin's rows. Operation for operation what BinMapping::bin and glm::min/max compute:
// _mm_min_ps(a, b) is (a < b ? a : b) and glm::min(x, y) is (y < x ? y : x), so glm::min(bin, ref) ==
// _mm_min_ps(ref, bin) bit for bit (signed zeros included), and likewise for max.
struct Binner {
  __m128 origin, scale, last_bin;
  uint32_t bin_count;

  explicit Binner(const BinMapping& mapping)
      : origin(_mm_setr_ps(mapping.origin.x, mapping.origin.y, mapping.origin.z, 0.0f)),
        scale(_mm_setr_ps(mapping.scale.x, mapping.scale.y, mapping.scale.z, 0.0f)),
        last_bin(_mm_set1_ps(static_cast<float>(mapping.bin_count - 1))),
        bin_count(mapping.bin_count) {}

  void add(const PrimRef& ref, SahBins& bins) const {
    const __m128 position = _mm_mul_ps(_mm_sub_ps(load_centroid(ref), origin), scale);
    // max(position, 0) maps NaN and everything not above 0 to bin 0, min() the top to the last bin,
    // and truncation does the rest, as in BinMapping::bin.
    alignas(16) int32_t bin[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(bin),
                    _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(position, _mm_setzero_ps()), last_bin)));
    const __m128 lo = _mm_loadu_ps(&ref.box_min.x);  // lane 3: the index bits, never read back
    const __m128 hi = _mm_loadu_ps(&ref.box_max.x);  // lane 3: centroid.x, likewise
    float* const mins = bins.box_min[0].data();
    float* const maxs = bins.box_max[0].data();
    for (int axis = 0; axis < 3; ++axis) {
      const uint32_t slot = static_cast<uint32_t>(axis) * bin_count + static_cast<uint32_t>(bin[axis]);
      _mm_storeu_ps(mins + 4 * slot, _mm_min_ps(lo, _mm_loadu_ps(mins + 4 * slot)));
      _mm_storeu_ps(maxs + 4 * slot, _mm_max_ps(hi, _mm_loadu_ps(maxs + 4 * slot)));
      ++bins.counts[slot];
    }
  }
};

// Neighbouring references mostly fall in the same bins, so binning one after the other chains every
// bin update on the previous one's store. Long ranges alternate between two sets of bins to halve
// those chains and merge them at the end; below this length clearing and merging the second set
// costs more than it saves.
constexpr uint32_t kTwoBinSetsFrom = 256;

// Bins refs[begin, end) into `bins` (not cleared here).
void bin_serial(std::span<const PrimRef> refs, uint32_t begin, uint32_t end, const BinMapping& mapping,
                SahBins& bins) {
  const Binner binner(mapping);
  if (end - begin < kTwoBinSetsFrom) {
    for (uint32_t i = begin; i != end; ++i) binner.add(refs[i], bins);
    return;
  }
  SahBins odd;  // 27 KB of stack, of which 3 * bin_count bins are cleared and used
  odd.clear(mapping.bin_count);
  uint32_t i = begin;
  for (; i + 1 < end; i += 2) {
    binner.add(refs[i], bins);
    binner.add(refs[i + 1], odd);
  }
  if (i != end) binner.add(refs[i], bins);
  // Minima, maxima and sums: the merged bins are the bins one set would have held.
  bins.add(odd);
}

// tbb::parallel_reduce body: a body is split off only when a thread steals work, so bins are
// cleared and merged once per stolen range, not once per chunk. The first body bins straight into
// the caller's bins (no 21 KB copy at the end); split-off bodies bin into their own. With
// block_counts, the range is one block index range (block b is refs[first + b * chunk, ...)), and
// each block's bin counts are recorded as the difference of the body's counts around it.
struct BinReduction {
  std::span<const PrimRef> refs;
  const BinMapping& mapping;
  SahBins own;
  SahBins* bins;
  BlockBinCounts* block_counts = nullptr;
  uint32_t first = 0, end = 0, chunk = 0;

  BinReduction(std::span<const PrimRef> r, const BinMapping& m, SahBins& out) : refs(r), mapping(m), bins(&out) {
    bins->clear(m.bin_count);
  }
  BinReduction(BinReduction& other, tbb::split)
      : refs(other.refs),
        mapping(other.mapping),
        bins(&own),
        block_counts(other.block_counts),
        first(other.first),
        end(other.end),
        chunk(other.chunk) {
    own.clear(mapping.bin_count);
  }
  BinReduction(const BinReduction&) = delete;
  BinReduction& operator=(const BinReduction&) = delete;
  void operator()(const tbb::blocked_range<uint32_t>& r) {
    if (block_counts == nullptr) {
      bin_serial(refs, r.begin(), r.end(), mapping, *bins);
      return;
    }
    const uint32_t slots = 3 * mapping.bin_count;
    for (uint32_t b = r.begin(); b != r.end(); ++b) {
      uint32_t* const counts = block_counts->block(b);
      std::copy_n(bins->counts.begin(), slots, counts);
      bin_serial(refs, first + b * chunk, std::min(end, first + (b + 1) * chunk), mapping, *bins);
      for (uint32_t k = 0; k < slots; ++k) counts[k] = bins->counts[k] - counts[k];
    }
  }
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
  const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
  const __m128 minus_inf = _mm_set1_ps(-std::numeric_limits<float>::infinity());
  for (uint32_t i = 0; i < 3 * count; ++i) {
    _mm_storeu_ps(box_min[i].data(), inf);
    _mm_storeu_ps(box_max[i].data(), minus_inf);
  }
  std::fill_n(counts.begin(), 3 * count, 0u);
}

void SahBins::add(const SahBins& other) {
  // Lane 3 is merged too; it is never read.
  for (uint32_t i = 0; i < 3 * bin_count; ++i) {
    SseBox box = SseBox::load(box_min[i].data(), box_max[i].data());
    box.extend(SseBox::load(other.box_min[i].data(), other.box_max[i].data()));
    _mm_storeu_ps(box_min[i].data(), box.lo);
    _mm_storeu_ps(box_max[i].data(), box.hi);
    counts[i] += other.counts[i];
  }
}

bool SahBins::operator==(const SahBins& other) const {
  if (bin_count != other.bin_count) return false;
  for (int axis = 0; axis < 3; ++axis)
    for (uint32_t b = 0; b < bin_count; ++b)
      if (count(axis, b) != other.count(axis, b) || box(axis, b).min != other.box(axis, b).min ||
          box(axis, b).max != other.box(axis, b).max)
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

void bin_refs_by_block(std::span<const PrimRef> refs, const PrimRange& range, const BinMapping& mapping,
                       uint32_t chunk, SahBins& bins, BlockBinCounts& block_counts) {
  const uint32_t blocks = (range.size() + chunk - 1) / chunk;
  block_counts.reset(blocks, 3 * mapping.bin_count);
  BinReduction reduction(refs, mapping, bins);
  reduction.block_counts = &block_counts;
  reduction.first = range.begin;
  reduction.end = range.end;
  reduction.chunk = chunk;
  tbb::parallel_reduce(tbb::blocked_range<uint32_t>(0, blocks, 1), reduction);
}

void BlockBinCounts::left_counts(int axis, uint32_t boundary, uint32_t bin_count, std::span<uint32_t> out) const {
  for (uint32_t b = 0; b < blocks_; ++b) {
    const uint32_t* const counts = block(b) + static_cast<uint32_t>(axis) * bin_count;
    uint32_t sum = 0;
    for (uint32_t k = 0; k < boundary; ++k) sum += counts[k];
    out[b] = sum;
  }
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
    const uint32_t* const counts = &bins.counts[bins.index(axis, 0)];
    const float* const mins = bins.box_min[bins.index(axis, 0)].data();
    const float* const maxs = bins.box_max[bins.index(axis, 0)].data();
    SseBox right;
    uint32_t right_count = 0;
    float cost_right = 0.0f;
    for (uint32_t b = bin_count - 1; b > 0; --b) {
      if (counts[b] != 0) {
        right.extend(SseBox::load(mins + 4 * b, maxs + 4 * b));
        right_count += counts[b];
        cost_right = right.half_area() * static_cast<float>(right_count);
      }
      right_cost[b] = cost_right;
    }
    SseBox left;
    uint32_t left_count = 0;
    for (uint32_t b = 1; b < bin_count; ++b) {
      if (counts[b - 1] == 0) continue;
      left.extend(SseBox::load(mins + 4 * (b - 1), maxs + 4 * (b - 1)));
      left_count += counts[b - 1];
      if (left_count == count) break;  // everything is left from here on
      const float cost = left.half_area() * static_cast<float>(left_count) + right_cost[b];
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
  // Boxes and the three bin indices of every reference up front, the bins as bin_serial computes
  // them (one SSE computation per reference instead of one branchy mapping per reference and axis).
  std::array<SseBox, kSmallSahRange> box;
  alignas(16) std::array<std::array<int32_t, 4>, kSmallSahRange> bins;
  const __m128 origin = _mm_setr_ps(mapping.origin.x, mapping.origin.y, mapping.origin.z, 0.0f);
  const __m128 scale = _mm_setr_ps(mapping.scale.x, mapping.scale.y, mapping.scale.z, 0.0f);
  const __m128 last_bin = _mm_set1_ps(static_cast<float>(mapping.bin_count - 1));
  const PrimRef* first = refs.data() + range.begin;
  for (uint32_t i = 0; i < count; ++i) {
    const PrimRef& ref = first[i];
    box[i] = SseBox::load(&ref.box_min.x, &ref.box_max.x);
    const __m128 position = _mm_mul_ps(_mm_sub_ps(load_centroid(ref), origin), scale);
    _mm_store_si128(reinterpret_cast<__m128i*>(bins[i].data()),
                    _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(position, _mm_setzero_ps()), last_bin)));
  }
  if (count == 2) {
    // The only split puts one reference on each side, at the same cost on every axis that separates
    // them (area(a) + area(b) == area(b) + area(a) in floats), so the general search below would
    // keep the first such axis: no sorting or sweeping needed.
    for (int axis = 0; axis < 3; ++axis) {
      const auto a = static_cast<size_t>(axis);
      if (mapping.scale[axis] == 0.0f || bins[0][a] == bins[1][a]) continue;
      const size_t low = bins[0][a] < bins[1][a] ? 0 : 1;
      const float cost = box[low].half_area() * 1.0f + box[1 - low].half_area() * 1.0f;
      if (!(cost < std::numeric_limits<float>::infinity())) return std::nullopt;  // as no boundary winning
      return SahSplit{axis, static_cast<uint32_t>(bins[low][a]) + 1, cost};
    }
    return std::nullopt;
  }
  std::array<uint32_t, kSmallSahRange> order;       // reference indices sorted by bin
  std::array<float, kSmallSahRange> right_cost_at;  // cost of order[i..] when order[i] starts a bin
  std::optional<SahSplit> best;
  float best_cost = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (mapping.scale[axis] == 0.0f) continue;
    const auto bin_of = [&](uint32_t i) { return bins[i][static_cast<size_t>(axis)]; };
    for (uint32_t i = 0; i < count; ++i) {
      order[i] = i;
      for (uint32_t j = i; j > 0 && bin_of(order[j - 1]) > bin_of(order[j]); --j) std::swap(order[j - 1], order[j]);
    }
    SseBox right;
    for (uint32_t i = count; i-- > 0;) {
      right.extend(box[order[i]]);
      if (i == 0 || bin_of(order[i - 1]) != bin_of(order[i]))
        right_cost_at[i] = right.half_area() * static_cast<float>(count - i);
    }
    SseBox left;
    for (uint32_t i = 0; i + 1 < count; ++i) {
      left.extend(box[order[i]]);
      const int32_t bin = bin_of(order[i]);
      if (bin == bin_of(order[i + 1])) continue;  // not the last reference of its bin
      const float cost = left.half_area() * static_cast<float>(i + 1) + right_cost_at[i + 1];
      if (cost < best_cost) {
        best_cost = cost;
        best = SahSplit{axis, static_cast<uint32_t>(bin) + 1, cost};
      }
    }
  }
  return best;
}

}  // namespace glint::accel::detail
