#include "accel/radix_sort.h"

#include "accel/parallel_array.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

namespace glint::accel {
namespace {

constexpr uint32_t kDigitBits = 8;
constexpr uint32_t kDigits = 1u << kDigitBits;
// Large enough that a chunk's histogram (1 KiB) and its scheduling are negligible next to its
// scatter, small enough that 600k keys give 16 cores about ten chunks each (with 16384, 38 chunks
// left the last of three rounds mostly idle).
constexpr size_t kChunkSize = 4096;

using Histogram = std::array<uint32_t, kDigits>;

// The digit of `key` at `shift`, keeping only bits below high_bit (a last digit may reach past it).
uint32_t digit_of(uint64_t key, uint32_t shift, uint32_t high_bit) {
  const uint64_t below_high = high_bit == 64 ? key : key & ((uint64_t{1} << high_bit) - 1);
  return static_cast<uint32_t>(below_high >> shift) & (kDigits - 1);
}

}  // namespace

void radix_sort_pairs(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t key_bits) {
  if (key_bits < 1 || key_bits > 64) fail("accel: radix_sort_pairs: key_bits must be in [1, 64], got {}", key_bits);
  radix_sort_pairs_by_bits(keys, values, 0, key_bits);
}

void radix_sort_pairs_by_bits(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit,
                              uint32_t high_bit) {
  if (keys.size() != values.size())
    fail("accel: radix_sort_pairs: {} keys but {} values", keys.size(), values.size());
  if (low_bit >= high_bit || high_bit > 64)
    fail("accel: radix_sort_pairs: bits [{}, {}) are not a range within [0, 64)", low_bit, high_bit);
  if (keys.size() >= (size_t{1} << 32)) fail("accel: radix_sort_pairs: {} pairs, at most 2^32 - 1", keys.size());
  const size_t count = keys.size();
  if (count < 2) return;

  const size_t chunk_count = (count + kChunkSize - 1) / kChunkSize;
  std::vector<Histogram> offsets(chunk_count);  // counts, then (after the prefix sum) output offsets
  // Passes alternate between the caller's arrays and these (filled in parallel, not by one thread).
  detail::ParallelArray<uint64_t> key_buffer(count, detail::kForOverwrite);
  detail::ParallelArray<uint32_t> value_buffer(count, detail::kForOverwrite);
  uint64_t* keys_in = keys.data();
  uint32_t* values_in = values.data();
  uint64_t* keys_out = key_buffer.data();
  uint32_t* values_out = value_buffer.data();
  const auto chunk_range = [&](size_t chunk) {
    return std::pair{chunk * kChunkSize, std::min(count, (chunk + 1) * kChunkSize)};
  };

  for (uint32_t shift = low_bit; shift < high_bit; shift += kDigitBits) {
    tbb::parallel_for(size_t{0}, chunk_count, [&](size_t chunk) {
      Histogram& histogram = offsets[chunk];
      histogram.fill(0);
      const auto [begin, end] = chunk_range(chunk);
      for (size_t i = begin; i != end; ++i) ++histogram[digit_of(keys_in[i], shift, high_bit)];
    });

    // Exclusive prefix sum in (digit, chunk) order: all keys with a smaller digit come first, then
    // those of the same digit from earlier chunks, which is what makes the pass stable.
    uint32_t running = 0;
    bool single_digit = false;
    for (uint32_t digit = 0; digit < kDigits; ++digit) {
      uint32_t digit_total = 0;
      for (size_t chunk = 0; chunk < chunk_count; ++chunk) {
        const uint32_t chunk_count_of_digit = offsets[chunk][digit];
        offsets[chunk][digit] = running;
        running += chunk_count_of_digit;
        digit_total += chunk_count_of_digit;
      }
      if (digit_total == count) single_digit = true;
    }
    if (single_digit) continue;  // every key has this digit: the pass would not move anything

    tbb::parallel_for(size_t{0}, chunk_count, [&](size_t chunk) {
      Histogram& next = offsets[chunk];
      const auto [begin, end] = chunk_range(chunk);
      for (size_t i = begin; i != end; ++i) {
        const uint32_t slot = next[digit_of(keys_in[i], shift, high_bit)]++;
        keys_out[slot] = keys_in[i];
        values_out[slot] = values_in[i];
      }
    });
    std::swap(keys_in, keys_out);
    std::swap(values_in, values_out);
  }
  if (keys_in == keys.data()) return;
  // An odd number of passes moved anything: the result is in the buffers.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kChunkSize), [&](const tbb::blocked_range<size_t>& r) {
    std::copy(keys_in + r.begin(), keys_in + r.end(), keys.data() + r.begin());
    std::copy(values_in + r.begin(), values_in + r.end(), values.data() + r.begin());
  });
}

}  // namespace glint::accel
