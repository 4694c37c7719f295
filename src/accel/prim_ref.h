#pragma once
// Internal to the top-down builders (median, sah): the record they sort, and a range of them.
// Splitting moves these 40-byte records rather than an index array into boxes and centroids, so every
// pass over a range (binning, partitioning, bounding) reads memory in order instead of gathering.
#include "accel/build_options.h"
#include "core/math.h"

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

// Bounds of refs[begin, end) (a PrimRange with those limits), with a TBB reduction over chunks of
// `chunk` references when `parallel`. Min and max are exact, so both ways give the same boxes.
PrimRange bound_refs(std::span<const PrimRef> refs, uint32_t begin, uint32_t end, bool parallel, uint32_t chunk);

// refs[i] = {input.boxes[i], i, input.centroids[i]} for every primitive, in parallel, and their bounds.
PrimRange make_prim_refs(const BuildInput& input, std::span<PrimRef> refs, uint32_t chunk);

}  // namespace glint::accel::detail
