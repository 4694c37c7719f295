#pragma once
// Internal to the top-down builders (median, sah): the record they sort, and a range of them.
// Splitting moves these 40-byte records rather than an index array into boxes and centroids, so every
// pass over a range (binning, partitioning, bounding) reads memory in order instead of gathering.
#include "accel/builders/build_options.h"
#include "accel/builders/sse_box.h"
#include "core/math.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

namespace glint::accel::detail {

struct PrimRef {
  vec3 box_min;
  uint32_t prim;  // index into BuildInput
  vec3 box_max;
  vec3 centroid;

  Aabb box() const { return {box_min, box_max}; }
};

// No default member initialisers on purpose: arrays of n references are allocated uninitialised and
// first written (and paged in) by parallel loops, not by one thread zeroing them.
static_assert(sizeof(PrimRef) == 40 && std::is_trivially_copyable_v<PrimRef> &&
              std::is_trivially_destructible_v<PrimRef>);

// A contiguous range [begin, end) of references and the boxes of what it holds.
struct PrimRange {
  uint32_t begin = 0;
  uint32_t end = 0;
  Aabb box;           // union of the primitive boxes
  Aabb centroid_box;  // bounds of the centroids

  uint32_t size() const { return end - begin; }
  void extend(const PrimRef& ref) {
    box.extend(Aabb{ref.box_min, ref.box_max});
    centroid_box.extend(ref.centroid);
  }
  void extend_bounds(const PrimRange& other) {
    box.extend(other.box);
    centroid_box.extend(other.centroid_box);
  }
};

// The centroid in lanes 0-2 (lane 3 unspecified). box_max.z and the centroid are the record's last
// 16 bytes: one load that stays inside the record, then a shuffle.
inline __m128 load_centroid(const PrimRef& ref) {
  const __m128 tail = _mm_loadu_ps(&ref.box_max.z);
  return _mm_shuffle_ps(tail, tail, _MM_SHUFFLE(3, 3, 2, 1));
}

// What PrimRange::extend accumulates, held in SSE registers for the loops that bound every reference
// they move (partitions, bounding). The same minima and maxima in the same order, so write() gives
// exactly the boxes PrimRange::extend would have given.
struct RangeBounds {
  SseBox box;
  SseBox centroids;

  void extend(const PrimRef& ref) {
    box.extend(SseBox::load(&ref.box_min.x, &ref.box_max.x));
    const __m128 centroid = load_centroid(ref);
    centroids.extend({centroid, centroid});
  }
  static RangeBounds of(const PrimRange& range) {
    return {SseBox::of(range.box), SseBox::of(range.centroid_box)};
  }
  void extend(const RangeBounds& other) {
    box.extend(other.box);
    centroids.extend(other.centroids);
  }
  // range's box and centroid_box become these bounds (begin and end are left as they are).
  void write(PrimRange& range) const {
    range.box = box.aabb();
    range.centroid_box = centroids.aabb();
  }
};

static_assert(offsetof(PrimRef, centroid) + sizeof(vec3) == sizeof(PrimRef) &&
              offsetof(PrimRef, box_max) + 2 * sizeof(float) + 16 == sizeof(PrimRef));

// Bounds of refs[begin, end) (a PrimRange with those limits), with a TBB reduction over chunks of
// `chunk` references when `parallel`. Min and max are exact, so both ways give the same boxes.
PrimRange bound_refs(std::span<const PrimRef> refs, uint32_t begin, uint32_t end, bool parallel, uint32_t chunk);

// refs[i] = {input.boxes[i], i, input.centroids[i]} for every primitive, in parallel, and their bounds.
PrimRange make_prim_refs(const BuildInput& input, std::span<PrimRef> refs, uint32_t chunk);

}  // namespace glint::accel::detail
