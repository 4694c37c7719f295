#include "accel/builders/builder.h"

#include "accel/builders/build_lbvh.h"
#include "accel/builders/build_median.h"
#include "accel/builders/build_none.h"
#include "accel/builders/build_ploc.h"
#include "accel/builders/build_sah.h"
#include "accel/builders/build_sbvh.h"
#include "accel/builders/build_trbvh.h"
#include "accel/builders/primitive_bounds.h"
#include "core/error.h"
#include "core/stopwatch.h"

#include <string>

namespace glint::accel {

namespace {

// The builders return the structure only; build_bvh times them, once.
Bvh build_untimed(BvhBuilder builder, const BuildInput& input, const BuildOptions& options) {
  switch (builder) {
    case BvhBuilder::none: return build_none(input, options);
    case BvhBuilder::median: return build_median(input, options);
    case BvhBuilder::sah: return build_sah(input, options);
    case BvhBuilder::sbvh: return build_sbvh(input, options);
    case BvhBuilder::lbvh: return build_lbvh(input, options);
    case BvhBuilder::trbvh: return build_trbvh(input, options);
    case BvhBuilder::ploc: return build_ploc(input, options);
  }
  fail("accel: invalid BvhBuilder value {}", static_cast<int>(builder));
}

}  // namespace

Bvh build_bvh(BvhBuilder builder, const BuildInput& input, const BuildOptions& options) {
  const Stopwatch watch;
  Bvh bvh = build_untimed(builder, input, options);
  bvh.build_ms = watch.elapsed_ms();
  return bvh;
}

Bvh build_bvh(BvhBuilder builder, const TriangleMesh& mesh, const BuildOptions& options) {
  const Stopwatch watch;
  Bvh bvh;
  if (builder == BvhBuilder::sbvh) {
    bvh = build_sbvh(mesh, options);
  } else {
    const detail::ScratchBounds bounds = detail::scratch_triangle_bounds(mesh);
    bvh = build_untimed(builder, bounds.input(), options);
  }
  bvh.build_ms = watch.elapsed_ms();
  return bvh;
}

void release_build_memory() { detail::release_retained_blocks(); }

}  // namespace glint::accel
