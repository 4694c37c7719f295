#include "cuda/gpu_bvh.h"

namespace glint::cuda {

std::vector<uint32_t> bvh_parents(const accel::Bvh& bvh) {
  std::vector<uint32_t> parents(bvh.nodes.size(), kNoParent);
  for (uint32_t i = 0; i < bvh.nodes.size(); ++i) {
    const accel::BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) continue;
    parents[node.left()] = i;
    parents[node.right()] = i;
  }
  return parents;
}

void GpuBvh::upload(const accel::Bvh& bvh, cudaStream_t stream) {
  nodes.upload(std::span<const accel::BvhNode>(bvh.nodes), stream);
  prim_indices.upload(std::span<const uint32_t>(bvh.prim_indices), stream);
  // The parent list is a temporary of this call: an asynchronous copy from pageable memory has
  // staged its source by the time it returns, so the list may go.
  const std::vector<uint32_t> parent_list = bvh_parents(bvh);
  parents.upload(std::span<const uint32_t>(parent_list), stream);
  depth = bvh.depth;
  refittable = bvh.refittable;
}

accel::Bvh GpuBvh::download(const char* builder) const {
  accel::Bvh bvh;
  const std::vector<accel::BvhNode> node_list = nodes.download();
  const std::vector<uint32_t> prim_list = prim_indices.download();
  bvh.nodes.assign(node_list.begin(), node_list.end());
  bvh.prim_indices.assign(prim_list.begin(), prim_list.end());
  bvh.depth = depth;
  bvh.refittable = refittable;
  bvh.builder = builder;
  return bvh;
}

}  // namespace glint::cuda
