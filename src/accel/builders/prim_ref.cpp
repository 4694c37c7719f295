#include "accel/builders/prim_ref.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace glint::accel::detail {
namespace {

PrimRange join_bounds(PrimRange a, const PrimRange& b) {
  a.extend_bounds(b);
  return a;
}

}  // namespace

PrimRange bound_refs(std::span<const PrimRef> refs, uint32_t begin, uint32_t end, bool parallel, uint32_t chunk) {
  const auto accumulate = [&](uint32_t from, uint32_t to, PrimRange acc) {
    RangeBounds bounds = RangeBounds::of(acc);
    for (uint32_t i = from; i != to; ++i) bounds.extend(refs[i]);
    bounds.write(acc);
    return acc;
  };
  const PrimRange empty{begin, end, {}, {}};
  if (!parallel || end - begin <= chunk) return accumulate(begin, end, empty);
  return tbb::parallel_reduce(
      tbb::blocked_range<uint32_t>(begin, end, chunk), empty,
      [&](const tbb::blocked_range<uint32_t>& r, PrimRange acc) { return accumulate(r.begin(), r.end(), acc); },
      join_bounds);
}

PrimRange make_prim_refs(const BuildInput& input, std::span<PrimRef> refs, uint32_t chunk) {
  const auto count = static_cast<uint32_t>(refs.size());
  return tbb::parallel_reduce(
      tbb::blocked_range<uint32_t>(0, count, chunk), PrimRange{0, count, {}, {}},
      [&](const tbb::blocked_range<uint32_t>& r, PrimRange acc) {
        RangeBounds bounds = RangeBounds::of(acc);
        for (uint32_t i = r.begin(); i != r.end(); ++i) {
          const Aabb& box = input.boxes[i];
          refs[i] = PrimRef{box.min, i, box.max, input.centroids[i]};
          bounds.extend(refs[i]);
        }
        bounds.write(acc);
        return acc;
      },
      join_bounds);
}

}  // namespace glint::accel::detail
