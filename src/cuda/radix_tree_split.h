#pragma once
// Karras 2012, "Maximizing parallelism in the construction of BVHs, octrees, and k-d trees",
// Figure 4, for one interior node: which end of its key range interior node i sits at, the other end
// (exponential then binary search) and the split position gamma (binary search), one node per
// thread of the GPU LBVH (gpu_lbvh.cu). The CPU LBVH builds the same tree bottom-up instead
// (accel/builders/build_lbvh.cpp): on a CPU one climb per leaf beats a search per node. `delta(a, b)` is
// the length of the common prefix of sorted keys a and b, and -1 when b is outside [0, leaf count).
#include "core/math.h"

#include <cstdint>

namespace glint::accel {

struct RadixTreeNode {
  int64_t first = 0;  // the node's key range [first, last]
  int64_t last = 0;
  int64_t gamma = 0;  // left child covers [first, gamma], right child [gamma + 1, last]

  // Children in the usual numbering: leaves 0..n-1, interior node k at n + k; a one-key range is a
  // leaf.
  GLINT_HOST_DEVICE int64_t left_child(int64_t leaf_count) const { return first == gamma ? gamma : leaf_count + gamma; }
  GLINT_HOST_DEVICE int64_t right_child(int64_t leaf_count) const {
    return last == gamma + 1 ? gamma + 1 : leaf_count + gamma + 1;
  }
};

template <typename Delta>
GLINT_HOST_DEVICE RadixTreeNode radix_tree_node(const Delta& delta, int64_t i) {
  const int d = delta(i, i + 1) > delta(i, i - 1) ? 1 : -1;
  const int delta_min = delta(i, i - d);
  int64_t length_max = 2;
  while (delta(i, i + length_max * d) > delta_min) length_max *= 2;
  int64_t length = 0;
  for (int64_t step = length_max / 2; step >= 1; step /= 2)
    if (delta(i, i + (length + step) * d) > delta_min) length += step;
  const int64_t j = i + length * d;

  const int delta_node = delta(i, j);
  int64_t split = 0;
  int64_t step = length;
  do {
    step = (step + 1) / 2;
    if (delta(i, i + (split + step) * d) > delta_node) split += step;
  } while (step > 1);
  const int64_t gamma = i + split * d + (d < 0 ? -1 : 0);
  return {i < j ? i : j, i < j ? j : i, gamma};
}

}  // namespace glint::accel
