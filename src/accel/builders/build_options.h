#pragma once
// What every builder takes: primitive boxes and centroids (not geometry, as in madmann91/bvh v2,
// so the same builders index triangles, instances or anything else) and a few knobs.
#include "core/math.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::accel {

struct BuildOptions {
  uint32_t max_leaf_size = 4;     // a leaf never holds more primitives than this
  // SAH costs, in the Aila-Karras-Laine 2013 convention used by bvh_stats too: traversing one
  // interior node costs traversal_cost, intersecting one primitive costs intersection_cost.
  float traversal_cost = 1.2f;
  float intersection_cost = 1.0f;
  uint32_t bins = 16;             // binned SAH: bins per axis, 2..256 (Wald 2007 uses 16-32)
  // Subtrees with at least this many primitives are built as separate TBB tasks; below it the
  // task overhead outweighs the work.
  uint32_t parallel_threshold = 4096;
  // trbvh: rounds of treelet restructuring after the LBVH (Karras & Aila 2013 use 3).
  uint32_t treelet_rounds = 3;
  // ploc: a cluster looks for its nearest neighbour among this many clusters on either side in
  // Morton order (Meister & Bittner 2018: 16 is close to the quality of larger radii), >= 1.
  uint32_t ploc_radius = 16;
};

// The builders' input. boxes[i] bounds primitive i; centroids[i] is the point used to sort it
// (usually the box centre). Both spans have the same size.
struct BuildInput {
  std::span<const Aabb> boxes;
  std::span<const vec3> centroids;
};

// Storage for a BuildInput computed from primitives.
struct PrimitiveBounds {
  std::vector<Aabb> boxes;
  std::vector<vec3> centroids;

  BuildInput input() const { return {boxes, centroids}; }
};

}  // namespace glint::accel
