#include "accel/builder.h"

#include "accel/build_lbvh.h"
#include "accel/build_median.h"
#include "accel/build_none.h"
#include "accel/build_ploc.h"
#include "accel/build_sah.h"
#include "accel/build_sbvh.h"
#include "accel/build_trbvh.h"
#include "accel/primitive_bounds.h"
#include "core/error.h"


#include <chrono>
#include <string>

namespace glint::accel {

Bvh build_bvh(BvhBuilder builder, const BuildInput& input, const BuildOptions& options) {
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

Bvh build_bvh(BvhBuilder builder, const TriangleMesh& mesh, const BuildOptions& options) {
  if (builder == BvhBuilder::sbvh) return build_sbvh(mesh, options);
  const auto start = std::chrono::steady_clock::now();
  const detail::ScratchBounds bounds = detail::scratch_triangle_bounds(mesh);
  Bvh bvh = build_bvh(builder, bounds.input(), options);
  bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

void release_build_memory() { detail::release_retained_blocks(); }

}  // namespace glint::accel
