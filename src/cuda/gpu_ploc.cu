#include "cuda/gpu_ploc.cuh"

#include "accel/bvh_node.h"
#include "accel/builders/primitive_bounds.h"

#include <cub/cub.cuh>

#include <bit>
#include <string>

namespace glint::cuda::detail {
namespace {

constexpr uint32_t kNoNeighbour = 0xFFFFFFFFu;

// As the CPU builder (accel/builders/build_ploc.cpp): among pairs at equal distance prefer neighbours
// (smaller gap), then pairs starting at an even position, then the earlier pair. With the
// distances symmetric, every candidate pair is strictly ordered by (distance, key), so the least
// pair of an iteration is mutual and every iteration merges at least once; the parity term halves
// runs of identical boxes in one iteration instead of merging one pair per iteration.
__device__ inline uint64_t tie_key(uint32_t i, uint32_t j) {
  const uint32_t first = i < j ? i : j, gap = (i < j ? j : i) - first;
  return (uint64_t{gap} << 33) | (uint64_t{first & 1u} << 32) | first;
}

__global__ void init_clusters_kernel(const Aabb* prim_boxes, const uint32_t* sorted_prims, uint32_t leaf_count,
                                     Aabb* tree_boxes, uint32_t* tree_sizes, PlocCluster* clusters) {
  const uint32_t leaf = blockIdx.x * blockDim.x + threadIdx.x;
  if (leaf >= leaf_count) return;
  const Aabb box = prim_boxes[sorted_prims[leaf]];
  tree_boxes[leaf] = box;
  tree_sizes[leaf] = 1;
  PlocCluster cluster;
  cluster.box = box;
  cluster.node = leaf;
  cluster.height = 1;
  clusters[leaf] = cluster;
}

// Smallest merged-box area within `radius` positions on either side. Each thread scans its own
// window; both ends of a pair compute the same distance (the same min/max and the same code).
__global__ void nearest_neighbour_kernel(const PlocCluster* clusters, uint32_t count, uint32_t radius,
                                         uint32_t* nearest) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const Aabb box = clusters[i].box;
  const uint32_t first = i > radius ? i - radius : 0;
  const uint32_t last = count - 1 - i > radius ? i + radius : count - 1;
  uint32_t best = kNoNeighbour;
  float best_distance = 0.0f;
  uint64_t best_key = 0;
  for (uint32_t j = first; j <= last; ++j) {
    if (j == i) continue;
    const float distance = accel::half_area(merged(box, clusters[j].box));
    const uint64_t key = tie_key(i, j);
    if (best == kNoNeighbour || distance < best_distance || (distance == best_distance && key < best_key)) {
      best = j;
      best_distance = distance;
      best_key = key;
    }
  }
  nearest[i] = best;
}

// The fallback that bounds the depth (see build_ploc_gpu): positions (0, 1), (2, 3), ... merge.
__global__ void pair_neighbours_kernel(uint32_t count, uint32_t* nearest) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  nearest[i] = (i ^ 1u) < count ? (i ^ 1u) : kNoNeighbour;
}

struct MergeRole {
  bool starts_merge;  // mutual pair, this is the lower position
  bool absorbed;      // mutual pair, this is the higher position
};

__device__ inline MergeRole merge_role(const uint32_t* nearest, uint32_t i) {
  const uint32_t partner = nearest[i];
  const bool mutual = partner != kNoNeighbour && nearest[partner] == i;
  return {mutual && i < partner, mutual && partner < i};
}

__global__ void merge_flags_kernel(const uint32_t* nearest, uint32_t count, uint64_t* flags) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const MergeRole role = merge_role(nearest, i);
  flags[i] = (uint64_t{role.starts_merge} << 32) | uint64_t{!role.absorbed};
}

// Survivors move to their prefix-sum slot; the lower end of each mutual pair makes the new tree
// node first_new_node + (merges before it), its children ordered by position (Morton order).
// Sizes of the children were written by earlier launches, so reading them here is race free.
__global__ void merge_compact_kernel(const PlocCluster* clusters, const uint32_t* nearest, const uint64_t* offsets,
                                     uint32_t count, uint32_t leaf_count, uint32_t first_new_node, uint2* children,
                                     uint32_t* parents, uint32_t* sizes, Aabb* boxes, PlocCluster* next,
                                     PlocProgress* progress) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const MergeRole role = merge_role(nearest, i);
  const uint64_t offset = offsets[i];
  const auto slot = static_cast<uint32_t>(offset);
  if (i == count - 1) progress->cluster_count = slot + (role.absorbed ? 0u : 1u);
  if (role.absorbed) return;
  if (!role.starts_merge) {
    next[slot] = clusters[i];
    return;
  }
  const PlocCluster a = clusters[i], b = clusters[nearest[i]];
  const uint32_t node = first_new_node + static_cast<uint32_t>(offset >> 32);
  PlocCluster cluster;
  cluster.box = merged(a.box, b.box);
  cluster.node = node;
  cluster.height = (a.height > b.height ? a.height : b.height) + 1;
  children[node - leaf_count] = make_uint2(a.node, b.node);
  parents[a.node] = node;
  parents[b.node] = node;
  sizes[node] = 1 + sizes[a.node] + sizes[b.node];
  boxes[node] = cluster.box;
  next[slot] = cluster;
  atomicMax(&progress->max_height, cluster.height);
}

uint32_t ceil_log2(uint32_t value) { return value <= 1 ? 0 : static_cast<uint32_t>(std::bit_width(value - 1)); }

}  // namespace

PlocScratch::~PlocScratch() {
  if (host_progress) cudaFreeHost(host_progress);  // not checked: a destructor, and a failed free leaks only
}

void build_ploc_gpu(const Aabb* prim_boxes, uint32_t count, uint32_t radius, PlocScratch& scratch, GpuBvh& out,
                    cudaStream_t stream) {
  scratch.morton.sort(prim_boxes, count, stream);
  BuildTree& tree = scratch.tree;
  tree.reset(count, stream);
  for (DeviceBuffer<PlocCluster>& clusters : scratch.clusters) clusters.resize(count);
  scratch.nearest.resize(count);
  scratch.merge_flags.resize(count);
  scratch.merge_offsets.resize(count);
  scratch.progress.resize(1);
  scratch.progress.fill_zero(stream);
  if (!scratch.host_progress) {
    void* pinned = nullptr;
    GLINT_CUDA_CHECK(cudaMallocHost(&pinned, sizeof(PlocProgress)));
    scratch.host_progress = static_cast<PlocProgress*>(pinned);
  }
  init_clusters_kernel<<<blocks_for(count), kBlockSize, 0, stream>>>(
      prim_boxes, scratch.morton.sorted_prims(), count, tree.boxes.data(), tree.sizes.data(),
      scratch.clusters[0].data());
  GLINT_CUDA_CHECK_LAUNCH();

  // The loop runs on the host and reads back the cluster count (and the tallest node) after every
  // iteration, a short synchronising copy: the grid sizes follow the count. H-PLOC (Benthin et al.
  // 2024) avoids that read back by clustering in one kernel along the LBVH's hierarchy; future work.
  //
  // Depth: greedy clustering can build chains (boxes shrinking along the curve merge one at a time),
  // deeper than traversal's fixed stack allows. With height h (of the tallest node) and c clusters,
  // pairing blindly from now on would end at height <= h + ceil(log2 c). An ordinary iteration is
  // run only while that bound stays <= kMaxBvhDepth after it (h + 1, c - 1); otherwise the clusters
  // are paired in Morton order, which keeps the bound, so the tree never exceeds kMaxBvhDepth. The
  // same fallback runs if an iteration merged nothing (only possible with NaN boxes).
  uint32_t cluster_count = count;
  uint32_t height = 1;
  bool stalled = false;
  int current = 0;
  while (cluster_count > 1) {
    const uint32_t blocks = blocks_for(cluster_count);
    uint32_t* nearest = scratch.nearest.data();
    const PlocCluster* clusters = scratch.clusters[current].data();
    if (stalled || height + 1 + ceil_log2(cluster_count - 1) > accel::kMaxBvhDepth) {
      pair_neighbours_kernel<<<blocks, kBlockSize, 0, stream>>>(cluster_count, nearest);
    } else {
      nearest_neighbour_kernel<<<blocks, kBlockSize, 0, stream>>>(clusters, cluster_count, radius, nearest);
    }
    GLINT_CUDA_CHECK_LAUNCH();
    merge_flags_kernel<<<blocks, kBlockSize, 0, stream>>>(nearest, cluster_count, scratch.merge_flags.data());
    GLINT_CUDA_CHECK_LAUNCH();
    std::size_t temp_bytes = 0;
    GLINT_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(nullptr, temp_bytes, scratch.merge_flags.data(),
                                                   scratch.merge_offsets.data(), cluster_count, stream));
    scratch.scan_temp.resize(temp_bytes);  // the largest count comes first: allocates on the first iteration only
    GLINT_CUDA_CHECK(cub::DeviceScan::ExclusiveSum(scratch.scan_temp.data(), temp_bytes, scratch.merge_flags.data(),
                                                   scratch.merge_offsets.data(), cluster_count, stream));
    // Every merge so far removed one cluster and made one node: count - cluster_count of them.
    const uint32_t first_new_node = count + (count - cluster_count);
    merge_compact_kernel<<<blocks, kBlockSize, 0, stream>>>(
        clusters, nearest, scratch.merge_offsets.data(), cluster_count, count, first_new_node, tree.children.data(),
        tree.parents.data(), tree.sizes.data(), tree.boxes.data(), scratch.clusters[1 - current].data(),
        scratch.progress.data());
    GLINT_CUDA_CHECK_LAUNCH();
    GLINT_CUDA_CHECK(cudaMemcpyAsync(scratch.host_progress, scratch.progress.data(), sizeof(PlocProgress),
                                     cudaMemcpyDeviceToHost, stream));
    GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
    const uint32_t previous_count = cluster_count;
    cluster_count = scratch.host_progress->cluster_count;
    height = scratch.host_progress->max_height > height ? scratch.host_progress->max_height : height;
    stalled = cluster_count == previous_count;
    if (cluster_count == 0 || cluster_count > previous_count)
      fail_message("ploc (GPU): iteration went from " + std::to_string(previous_count) + " to " +
                   std::to_string(cluster_count) + " clusters");
    current = 1 - current;
  }
  // The last iteration merges the last two clusters, making the last node: 2 count - 2.
  const uint32_t root = 2 * count - 2;
  write_flat_layout(tree, scratch.morton.sorted_prims(), count, root, out, stream);
}

}  // namespace glint::cuda::detail
