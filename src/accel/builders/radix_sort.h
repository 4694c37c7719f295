#pragma once
// Parallel radix sort of (key, value) pairs, the sorting step of the Morton-code builders (lbvh,
// trbvh, ploc). Own implementation on oneTBB. A parallel pass: every fixed-size chunk counts its
// 8-bit digits, one prefix sum over (digit, chunk) gives every chunk its output offsets, and the
// chunks scatter in parallel. Short inputs take such passes from the lowest digit up (LSD); long
// ones take one on their top digit, then every bucket is sorted by one thread in cache. Chunks keep
// their input order, so the sort is stable and its output does not depend on the number of threads.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

namespace glint::accel {

// Sorts keys ascending, moving values along; equal keys keep their relative order. Only the low
// `key_bits` bits of every key take part (the others must be zero); key_bits in [1, 64], glint::Error
// otherwise or when the spans differ in size. Passes in which every key has the same digit are
// skipped, so sorting 30-bit codes costs 4 passes and already sorted digits cost no scatter.
void radix_sort_pairs(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t key_bits);

// The same, ordering by bits [low_bit, high_bit) of the keys only (0 <= low_bit < high_bit <= 64);
// the other bits do not take part and need not be zero, and keys are moved whole. Pairs equal in
// those bits keep their order.
void radix_sort_pairs_by_bits(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit,
                              uint32_t high_bit);

// The same, calling visit(begin, end) on consecutive ranges that together cover the arrays, each
// once it is sorted (from several threads at once), so that the caller can go on with a range while
// it is still in cache. Pairs equal in bits [low_bit, high_bit) always share a range.
using SortedRangeVisitor = std::function<void(size_t begin, size_t end)>;
void radix_sort_pairs_by_bits(std::span<uint64_t> keys, std::span<uint32_t> values, uint32_t low_bit,
                              uint32_t high_bit, const SortedRangeVisitor& visit);

// Stable insertion sort of short arrays of (key, value) pairs by sort_key(key, value), for the
// buckets and runs too short for radix passes. Each pair is held while the larger ones move up, then
// written once: swapping neighbours instead re-read what the step before had just written, and
// stalled on store forwarding.
template <typename SortKey>
void insertion_sort_pairs(std::span<uint64_t> keys, std::span<uint32_t> values, SortKey&& sort_key) {
  for (size_t i = 1; i < keys.size(); ++i) {
    const uint64_t key = keys[i];
    const uint32_t value = values[i];
    const auto held = sort_key(key, value);
    size_t j = i;
    for (; j > 0 && sort_key(keys[j - 1], values[j - 1]) > held; --j) {
      keys[j] = keys[j - 1];
      values[j] = values[j - 1];
    }
    keys[j] = key;
    values[j] = value;
  }
}

}  // namespace glint::accel
