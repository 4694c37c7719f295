#include "accel/builders/radix_sort.h"

#include "accel/builders/parallel_array.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace glint::accel {
namespace {

constexpr uint32_t kDigitBits = 8;
constexpr uint32_t kDigits = 1u << kDigitBits;
// Large enough that a chunk's histogram (1 KiB) and its scheduling are negligible next to its
// scatter, small enough that 600k keys give 16 cores about ten chunks each (with 16384, 38 chunks
// left the last of three rounds mostly idle).
constexpr size_t kChunkSize = 4096;

// Inputs this long or longer are sorted bucket by bucket: one parallel pass on the top digit, then
// every bucket on its own, in cache. Each of the LSD passes below would read and write the whole
// array from memory instead (four passes for Morton codes).
constexpr size_t kBucketSortMinCount = size_t{1} << 16;
// A bucket up to this long is sorted by one thread in cache (12 bytes a pair, and as much scratch:
// 384 KiB, within a core's L2); a longer one bucket by bucket again, on its next 8 bits. A
// bucket of 60k pairs sorted by one thread was the tail of the whole sort on 16 cores.
constexpr size_t kLocalSortMaxCount = size_t{1} << 14;
// Digits of the in-cache passes: 2048 counters fit in L1 and two passes cover 22 bits.
constexpr uint32_t kLocalDigitBits = 11;
constexpr uint32_t kMaxLocalPasses = (64 + kLocalDigitBits - 1) / kLocalDigitBits;
// Buckets this short are insertion-sorted.
constexpr size_t kInsertionSortMaxCount = 32;

using Histogram = std::array<uint32_t, kDigits>;

// Bits [low_bit, high_bit) of `key`, shifted down.
uint64_t bits_of(uint64_t key, uint32_t low_bit, uint32_t high_bit) {
  const uint64_t below_high = high_bit == 64 ? key : key & ((uint64_t{1} << high_bit) - 1);
  return below_high >> low_bit;
}

// The digit of `key` at `shift`, keeping only bits below high_bit (a last digit may reach past it).
uint32_t digit_of(uint64_t key, uint32_t shift, uint32_t high_bit) {
  return static_cast<uint32_t>(bits_of(key, shift, high_bit)) & (kDigits - 1);
}

struct PairArrays {
  uint64_t* keys;
  uint32_t* values;
};

// One parallel, stable scatter of `count` pairs by their 8-bit digit at `shift` from `in` to `out`.
// Returns the number of pairs with each digit, or nothing when every pair has the same digit (the
// pass would not move anything, so it writes nothing).
std::optional<Histogram> scatter_by_digit(PairArrays in, PairArrays out, size_t count, uint32_t shift,
                                          uint32_t high_bit, std::vector<Histogram>& offsets) {
  const size_t chunk_count = (count + kChunkSize - 1) / kChunkSize;
  offsets.resize(chunk_count);  // counts, then (after the prefix sum) output offsets
  const auto chunk_range = [&](size_t chunk) {
    return std::pair{chunk * kChunkSize, std::min(count, (chunk + 1) * kChunkSize)};
  };
  tbb::parallel_for(size_t{0}, chunk_count, [&](size_t chunk) {
    Histogram& histogram = offsets[chunk];
    histogram.fill(0);
    const auto [begin, end] = chunk_range(chunk);
    for (size_t i = begin; i != end; ++i) ++histogram[digit_of(in.keys[i], shift, high_bit)];
  });

  // Exclusive prefix sum in (digit, chunk) order: all keys with a smaller digit come first, then
  // those of the same digit from earlier chunks, which is what makes the pass stable.
  Histogram totals{};
  uint32_t running = 0;
  for (uint32_t digit = 0; digit < kDigits; ++digit) {
    for (size_t chunk = 0; chunk < chunk_count; ++chunk) {
      const uint32_t chunk_count_of_digit = offsets[chunk][digit];
      offsets[chunk][digit] = running;
      running += chunk_count_of_digit;
      totals[digit] += chunk_count_of_digit;
    }
    if (totals[digit] == count) return std::nullopt;
  }

  tbb::parallel_for(size_t{0}, chunk_count, [&](size_t chunk) {
    Histogram& next = offsets[chunk];
    const auto [begin, end] = chunk_range(chunk);
    for (size_t i = begin; i != end; ++i) {
      const uint32_t slot = next[digit_of(in.keys[i], shift, high_bit)]++;
      out.keys[slot] = in.keys[i];
      out.values[slot] = in.values[i];
    }
  });
  return totals;
}

void copy_pairs(PairArrays from, PairArrays to, size_t count) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kChunkSize), [&](const tbb::blocked_range<size_t>& r) {
    std::copy(from.keys + r.begin(), from.keys + r.end(), to.keys + r.begin());
    std::copy(from.values + r.begin(), from.values + r.end(), to.values + r.begin());
  });
}

// LSD passes of 8-bit digits from low_bit up, alternating between `data` and same-sized buffers.
void sort_by_lsd_passes(PairArrays data, size_t count, uint32_t low_bit, uint32_t high_bit) {
  // Filled in parallel, not by one thread.
  detail::ParallelArray<uint64_t> key_buffer(count, detail::kForOverwrite);
  detail::ParallelArray<uint32_t> value_buffer(count, detail::kForOverwrite);
  PairArrays in = data;
  PairArrays out{key_buffer.data(), value_buffer.data()};
  std::vector<Histogram> offsets;
  for (uint32_t shift = low_bit; shift < high_bit; shift += kDigitBits)
    if (scatter_by_digit(in, out, count, shift, high_bit, offsets)) std::swap(in, out);
  // An odd number of passes moved anything: the result is in the buffers.
  if (in.keys != data.keys) copy_pairs(in, data, count);
}

// Scratch for sort_in_cache: one per thread, as long as the longest bucket it sorted.
struct LocalScratch {
  std::vector<uint64_t> keys;
  std::vector<uint32_t> values;
};

// Sorts the `count` pairs at `from` by bits [low_bit, high_bit) into `to`, stably, by one thread:
// LSD passes of kLocalDigitBits, their histograms counted in one read, passes whose digit never
// changes skipped, and the ping-pong arranged so that the last pass writes `to`.
void sort_in_cache(PairArrays from, PairArrays to, size_t count, uint32_t low_bit, uint32_t high_bit,
                   LocalScratch& scratch) {
  if (count <= kInsertionSortMaxCount) {
    std::copy(from.keys, from.keys + count, to.keys);
    std::copy(from.values, from.values + count, to.values);
    insertion_sort_pairs(std::span(to.keys, count), std::span(to.values, count),
                         [&](uint64_t key, uint32_t) { return bits_of(key, low_bit, high_bit); });
    return;
  }
  constexpr uint32_t kLocalDigits = 1u << kLocalDigitBits;
  using LocalHistogram = std::array<uint32_t, kLocalDigits>;
  const uint32_t pass_count = (high_bit - low_bit + kLocalDigitBits - 1) / kLocalDigitBits;
  std::array<LocalHistogram, kMaxLocalPasses> histograms;
  for (uint32_t pass = 0; pass < pass_count; ++pass) histograms[pass].fill(0);
  const auto local_digit = [&](uint64_t key, uint32_t pass) {
    return static_cast<uint32_t>(bits_of(key, low_bit + pass * kLocalDigitBits, high_bit)) & (kLocalDigits - 1);
  };
  for (size_t i = 0; i < count; ++i)
    for (uint32_t pass = 0; pass < pass_count; ++pass) ++histograms[pass][local_digit(from.keys[i], pass)];
  std::array<uint32_t, kMaxLocalPasses> moving{};
  uint32_t moving_count = 0;
  for (uint32_t pass = 0; pass < pass_count; ++pass)
    if (std::find(histograms[pass].begin(), histograms[pass].end(), count) == histograms[pass].end())
      moving[moving_count++] = pass;
  if (moving_count == 0) {
    std::copy(from.keys, from.keys + count, to.keys);
    std::copy(from.values, from.values + count, to.values);
    return;
  }
  if (scratch.keys.size() < count) {
    scratch.keys.resize(count);
    scratch.values.resize(count);
  }
  const PairArrays spare{scratch.keys.data(), scratch.values.data()};
  PairArrays in = from;
  for (uint32_t m = 0; m < moving_count; ++m) {
    // Counting back from the last pass, which writes `to`, the targets alternate with the spare.
    const PairArrays out = (moving_count - m) % 2 == 1 ? to : spare;
    const uint32_t pass = moving[m];
    LocalHistogram& next = histograms[pass];
    uint32_t running = 0;
    for (uint32_t& slot : next) running += std::exchange(slot, running);
    for (size_t i = 0; i < count; ++i) {
      const uint32_t slot = next[local_digit(in.keys[i], pass)]++;
      out.keys[slot] = in.keys[i];
      out.values[slot] = in.values[i];
    }
    in = out;
  }
}

// `visit` (may be null) gets ranges of `data`, as radix_sort_pairs_by_bits documents.
void sort_pairs(PairArrays data, size_t count, uint32_t low_bit, uint32_t high_bit, const SortedRangeVisitor* visit);

// One parallel pass on the top 8 bits from `source` into buffers, then every bucket sorted by the
// remaining bits into `data` (which may be `source`): in cache by one thread, or, when long, bucket
// by bucket again.
void sort_by_buckets(PairArrays source, PairArrays data, size_t count, uint32_t low_bit, uint32_t high_bit,
                     const SortedRangeVisitor* visit) {
  const uint32_t top_shift = high_bit - kDigitBits;
  detail::ParallelArray<uint64_t> key_buffer(count, detail::kForOverwrite);
  detail::ParallelArray<uint32_t> value_buffer(count, detail::kForOverwrite);
  const PairArrays buckets{key_buffer.data(), value_buffer.data()};
  std::vector<Histogram> offsets;
  const std::optional<Histogram> sizes = scatter_by_digit(source, buckets, count, top_shift, high_bit, offsets);
  if (!sizes) {  // one bucket: the top bits are already in order
    if (source.keys != data.keys) copy_pairs(source, data, count);
    sort_pairs(data, count, low_bit, top_shift, visit);
    return;
  }
  std::array<size_t, kDigits + 1> starts{};
  for (uint32_t digit = 0; digit < kDigits; ++digit) starts[digit + 1] = starts[digit] + (*sizes)[digit];
  tbb::enumerable_thread_specific<LocalScratch> scratch;
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, kDigits, 1), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t digit = r.begin(); digit != r.end(); ++digit) {
      const size_t begin = starts[digit], size = starts[digit + 1] - begin;
      if (size == 0) continue;
      const PairArrays from{buckets.keys + begin, buckets.values + begin};
      const PairArrays to{data.keys + begin, data.values + begin};
      if (size <= kLocalSortMaxCount) {
        sort_in_cache(from, to, size, low_bit, top_shift, scratch.local());
        if (visit) (*visit)(begin, begin + size);
      } else {
        // Sorted into where it belongs, so that its own buckets are visited as they finish, in
        // parallel, rather than the whole of it by one thread at the end.
        const SortedRangeVisitor shifted = [&](size_t first, size_t last) { (*visit)(begin + first, begin + last); };
        const SortedRangeVisitor* shifted_visit = visit ? &shifted : nullptr;
        if (top_shift - low_bit > kDigitBits) {
          sort_by_buckets(from, to, size, low_bit, top_shift, shifted_visit);
        } else {
          copy_pairs(from, to, size);
          sort_pairs(to, size, low_bit, top_shift, shifted_visit);
        }
      }
    }
  });
}

// Stable sort of `count` pairs by bits [low_bit, high_bit) of their keys, in place.
void sort_pairs(PairArrays data, size_t count, uint32_t low_bit, uint32_t high_bit, const SortedRangeVisitor* visit) {
  if (count >= kBucketSortMinCount && high_bit - low_bit > kDigitBits) {
    sort_by_buckets(data, data, count, low_bit, high_bit, visit);
    return;
  }
  if (count >= 2 && low_bit < high_bit) sort_by_lsd_passes(data, count, low_bit, high_bit);
  if (visit && count > 0) (*visit)(0, count);
}

void check_arguments(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit, uint32_t high_bit) {
  if (keys.size() != values.size())
    fail("accel: radix_sort_pairs: {} keys but {} values", keys.size(), values.size());
  if (low_bit >= high_bit || high_bit > 64)
    fail("accel: radix_sort_pairs: bits [{}, {}) are not a range within [0, 64)", low_bit, high_bit);
  if (keys.size() >= (size_t{1} << 32)) fail("accel: radix_sort_pairs: {} pairs, at most 2^32 - 1", keys.size());
}

}  // namespace

void radix_sort_pairs(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t key_bits) {
  if (key_bits < 1 || key_bits > 64) fail("accel: radix_sort_pairs: key_bits must be in [1, 64], got {}", key_bits);
  radix_sort_pairs_by_bits(keys, values, 0, key_bits);
}

void radix_sort_pairs_by_bits(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit,
                              uint32_t high_bit) {
  check_arguments(keys, values, low_bit, high_bit);
  sort_pairs(PairArrays{keys.data(), values.data()}, keys.size(), low_bit, high_bit, nullptr);
}

void radix_sort_pairs_by_bits(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit,
                              uint32_t high_bit, const SortedRangeVisitor& visit) {
  check_arguments(keys, values, low_bit, high_bit);
  sort_pairs(PairArrays{keys.data(), values.data()}, keys.size(), low_bit, high_bit, &visit);
}

}  // namespace glint::accel
