#pragma once
// The top-down builders' references over a test scene's primitives, for tests of binning and
// partitioning (shared by parallel_build_test and sah_block_binning_test).
#include "accel/builders/build_options.h"
#include "accel/builders/prim_ref.h"

#include <vector>

namespace glint::accel::testing {

// refs[i] for primitive i, in parallel chunks of 1024; `root` gets their bounds.
inline std::vector<detail::PrimRef> make_refs(const PrimitiveBounds& bounds, detail::PrimRange& root) {
  std::vector<detail::PrimRef> refs(bounds.boxes.size());
  root = detail::make_prim_refs(bounds.input(), refs, 1024);
  return refs;
}

}  // namespace glint::accel::testing
