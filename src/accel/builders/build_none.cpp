#include "accel/builders/build_none.h"

#include "core/error.h"

#include <numeric>

namespace glint::accel {

Bvh build_none(const BuildInput& input, const BuildOptions& /*options*/) {
  if (input.boxes.size() != input.centroids.size())
    fail("accel: build_none: {} boxes but {} centroids", input.boxes.size(), input.centroids.size());
  if (input.boxes.size() >= (size_t{1} << 31))
    fail("accel: build_none: {} primitives, at most 2^31 - 1", input.boxes.size());
  Bvh bvh;
  bvh.builder = "none";
  const auto count = static_cast<uint32_t>(input.boxes.size());
  bvh.prim_indices.resize(count);
  std::iota(bvh.prim_indices.begin(), bvh.prim_indices.end(), 0u);
  if (count > 0) {
    Aabb box;
    for (const Aabb& prim_box : input.boxes) box.extend(prim_box);
    BvhNode root;
    root.set_bounds(box);
    root.first = 0;
    root.prim_count = count;
    bvh.nodes.push_back(root);
    bvh.depth = 1;
  }
  return bvh;
}

}  // namespace glint::accel
