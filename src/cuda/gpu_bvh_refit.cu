#include "cuda/gpu_bvh_build.h"

#include "cuda/gpu_bvh_layout.cuh"

#include <algorithm>
#include <string>
#include <vector>

namespace glint::cuda {
namespace {

// One BVH of a refit launch: its leaves' boxes come from prim_boxes (indexed by the leaf slots'
// primitives) or, where prim_boxes is null, straight from its mesh's triangles.
struct RefitJob {
  accel::BvhNode* nodes = nullptr;
  const uint32_t* prim_indices = nullptr;
  const uint32_t* parents = nullptr;
  const Aabb* prim_boxes = nullptr;
  accel::TriangleMesh mesh;
  uint32_t node_count = 0;
  uint32_t first_thread = 0;  // the launch's threads [first_thread, first_thread + node_count) are this BVH's
  uint32_t* arrivals = nullptr;
};

// Up to kMaxRefitJobs BVHs in one launch (kernel parameters), so that the climbs of a frame's
// deforming meshes run side by side instead of one after another: a climb's time is its depth in
// dependent L2 round trips, not its width.
constexpr uint32_t kMaxRefitJobs = 16;
struct RefitBatch {
  RefitJob jobs[kMaxRefitJobs];
  uint32_t count = 0;
  uint32_t threads = 0;
};

// One thread per node; leaves take the union of their primitives' boxes, then climb through the
// parent links. The first thread to arrive at a node stops; the second (its sibling subtree is
// done) computes the node's box from both children, sets the node's counter back to 0 for the next
// refit (nothing else arrives there in this one) and goes on. __threadfence() before the arrival
// publishes this thread's boxes; the one after it orders the sibling's box, read from L2, after the
// arrival. Only the bounds are written: the topology (first, prim_count) is read with plain loads.
// A climb is a chain of dependent round trips to L2, so each level waits on as few as it can: the
// thread carries its own child's box and reads only the sibling's, and reads the fixed topology (the
// node's children, its parent) before its arrival, not after (docs/perf.md "Twelfth round").
__global__ void refit_kernel(const RefitBatch batch) {
  const uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  if (thread >= batch.threads) return;
  uint32_t j = 0;
  while (j + 1 < batch.count && thread >= batch.jobs[j + 1].first_thread) ++j;
  const RefitJob& job = batch.jobs[j];
  const uint32_t leaf = thread - job.first_thread;
  if (leaf >= job.node_count) return;
  accel::BvhNode* nodes = job.nodes;
  const uint32_t first = nodes[leaf].first, prim_count = nodes[leaf].prim_count;
  if (prim_count == 0) return;
  Aabb box;
  for (uint32_t slot = first; slot != first + prim_count; ++slot) {
    const uint32_t prim = job.prim_indices[slot];
    box.extend(job.prim_boxes != nullptr ? job.prim_boxes[prim] : job.mesh.triangle(prim).bounds());
  }
  nodes[leaf].bounds_min = box.min;
  nodes[leaf].bounds_max = box.max;
  uint32_t child = leaf;
  for (uint32_t node = job.parents[leaf]; node != kNoParent;) {
    const uint32_t left = nodes[node].first, parent = job.parents[node];
    __threadfence();
    if (atomicAdd(&job.arrivals[node], 1u) == 0) return;
    job.arrivals[node] = 0;
    __threadfence();
    // The left child's box first, as accel::refit merges (min and max of 0 and -0 may depend on it).
    const bool from_left = child == left;
    const Aabb sibling = detail::load_node_box_from_l2(&nodes[from_left ? left + 1 : left]);
    box = from_left ? detail::merged(box, sibling) : detail::merged(sibling, box);
    nodes[node].bounds_min = box.min;
    nodes[node].bounds_max = box.max;
    child = node;
    node = parent;
  }
}

// One thread per leaf counts the levels up to the root.
__global__ void depth_kernel(const accel::BvhNode* nodes, const uint32_t* parents, uint32_t node_count,
                             uint32_t* depth) {
  const uint32_t leaf = blockIdx.x * blockDim.x + threadIdx.x;
  if (leaf >= node_count || nodes[leaf].prim_count == 0) return;
  uint32_t levels = 1;
  for (uint32_t node = parents[leaf]; node != kNoParent; node = parents[node]) ++levels;
  atomicMax(depth, levels);
}

void check_parents(const GpuBvh& bvh, const char* what) {
  if (bvh.parents.size() != bvh.nodes.size())
    fail_message(std::string(what) + ": the BVH has " + std::to_string(bvh.parents.size()) + " parent links for " +
                 std::to_string(bvh.nodes.size()) + " nodes (upload it with GpuBvh::upload or build it on the GPU)");
}

// The job of one BVH; its arrival counters are zeroed only when their count changes (a refit leaves
// them at 0).
RefitJob refit_job(GpuBvh& bvh, DeviceBuffer<uint32_t>& counters, cudaStream_t stream, const char* what) {
  if (!bvh.refittable)
    fail_message(std::string(what) + ": this BVH is not refittable (its leaves hold split references); rebuild it instead");
  check_parents(bvh, what);
  const uint32_t node_count = bvh.node_count();
  if (counters.size() != node_count) {
    counters.resize(node_count);
    counters.fill_zero(stream);
  }
  RefitJob job;
  job.nodes = bvh.nodes.data();
  job.prim_indices = bvh.prim_indices.data();
  job.parents = bvh.parents.data();
  job.node_count = node_count;
  job.arrivals = counters.data();
  return job;
}

void launch_refit(std::span<const RefitJob> jobs, cudaStream_t stream) {
  for (std::size_t start = 0; start < jobs.size(); start += kMaxRefitJobs) {
    RefitBatch batch;
    for (std::size_t i = start; i < std::min(jobs.size(), start + kMaxRefitJobs); ++i) {
      if (jobs[i].node_count == 0) continue;
      batch.jobs[batch.count] = jobs[i];
      batch.jobs[batch.count].first_thread = batch.threads;
      batch.threads += jobs[i].node_count;
      ++batch.count;
    }
    if (batch.count == 0) continue;
    refit_kernel<<<detail::blocks_for(batch.threads), detail::kBlockSize, 0, stream>>>(batch);
    GLINT_CUDA_CHECK_LAUNCH();
  }
}

}  // namespace

void refit_gpu(GpuBvh& bvh, const Aabb* prim_boxes, DeviceBuffer<uint32_t>& counters, cudaStream_t stream) {
  RefitJob job = refit_job(bvh, counters, stream, "refit_gpu");
  job.prim_boxes = prim_boxes;
  launch_refit(std::span<const RefitJob>(&job, 1), stream);
}

void refit_meshes_gpu(std::span<const MeshRefit> refits, cudaStream_t stream) {
  std::vector<RefitJob> jobs;
  jobs.reserve(refits.size());
  for (const MeshRefit& refit : refits) {
    if (refit.mesh.triangle_count == 0 && refit.bvh->node_count() != 0)
      fail_message("refit_meshes_gpu: a BVH over an empty mesh");
    jobs.push_back(refit_job(*refit.bvh, *refit.counters, stream, "refit_meshes_gpu"));
    jobs.back().mesh = refit.mesh;
  }
  launch_refit(jobs, stream);
}

uint32_t measure_depth(const GpuBvh& bvh, cudaStream_t stream) {
  check_parents(bvh, "measure_depth");
  const uint32_t node_count = bvh.node_count();
  if (node_count == 0) return 0;
  DeviceBuffer<uint32_t> depth(1);
  depth.fill_zero(stream);
  depth_kernel<<<detail::blocks_for(node_count), detail::kBlockSize, 0, stream>>>(bvh.nodes.data(), bvh.parents.data(),
                                                                                  node_count, depth.data());
  GLINT_CUDA_CHECK_LAUNCH();
  uint32_t levels = 0;
  GLINT_CUDA_CHECK(cudaMemcpyAsync(&levels, depth.data(), sizeof(levels), cudaMemcpyDeviceToHost, stream));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  return levels;
}

}  // namespace glint::cuda
