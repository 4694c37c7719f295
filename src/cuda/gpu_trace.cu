#include "cuda/gpu_trace.h"

#include "accel/kdtree/kdtree_traverse.h"
#include "cuda/cuda_check.h"
#include "cuda/gpu_traverse.cuh"

#include <algorithm>

namespace glint::cuda {
namespace {

// 128 threads a block; every thread keeps two 64-entry stacks (node, entry distance) in local memory.
constexpr uint32_t kTraceBlock = 128;
constexpr uint32_t kBoxBlock = 128;
constexpr uint32_t kWarp = 32;

__device__ inline accel::Ray load_ray(const accel::Ray* rays, uint32_t i) {
  const float4* raw = reinterpret_cast<const float4*>(rays + i);
  const float4 low = __ldg(raw);
  const float4 high = __ldg(raw + 1);
  accel::Ray ray;
  ray.origin = vec3(low.x, low.y, low.z);
  ray.t_min = low.w;
  ray.direction = vec3(high.x, high.y, high.z);
  ray.t_max = high.w;
  return ray;
}

// What one thread does with ray slot i, per query and kind of structure: trace it, write its result.
// View: accel::TlasView (BVH BLASes) or accel::KdTlasView (kd-tree BLASes), each its own kernel.
template <typename View>
struct TwoLevelTrace {
  View tlas;
  __device__ void operator()(const TraceLaunch& launch, uint32_t i, const accel::Ray& ray, bool& overflow) const {
    launch.hits[i] = gpu_trace_closest(tlas, ray, overflow);
  }
};

template <typename View>
struct TwoLevelOcclusion {
  View tlas;
  __device__ void operator()(const TraceLaunch& launch, uint32_t i, const accel::Ray& ray, bool& overflow) const {
    launch.occluded[i] = gpu_trace_any(tlas, ray, overflow) ? 1u : 0u;
  }
};

struct SingleLevelTrace {
  accel::Blas blas;
  __device__ void operator()(const TraceLaunch& launch, uint32_t i, const accel::Ray& ray, bool& overflow) const {
    accel::Hit hit;
    float t_max = ray.t_max;
    if (gpu_intersect_closest(blas, ray.origin, ray.direction, ray.t_min, t_max, hit, overflow)) hit.instance = 0;
    launch.hits[i] = hit;
  }
};

template <typename TraceOne>
__device__ inline void trace_slot(const TraceOne& trace_one, const TraceLaunch& launch, uint32_t i) {
  bool overflowed = false;
  trace_one(launch, i, load_ray(launch.rays, i), overflowed);
  if (overflowed) atomicOr(launch.overflow, 1u);
}

__device__ inline uint32_t ray_total(const TraceLaunch& launch) {
  return launch.ray_count ? min(*launch.ray_count, launch.capacity) : launch.capacity;
}

template <typename TraceOne>
__global__ void __launch_bounds__(kTraceBlock) one_ray_per_thread_kernel(TraceOne trace_one, TraceLaunch launch) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < ray_total(launch)) trace_slot(trace_one, launch, i);
}

// Persistent warps: each warp takes 32 consecutive rays at a time from launch.next_ray (one atomic
// per warp, its lane 0's, broadcast with a shuffle) until the list is exhausted. The lanes stay
// together through the loop, so the full-mask shuffle is legal.
template <typename TraceOne>
__global__ void __launch_bounds__(kTraceBlock) persistent_kernel(TraceOne trace_one, TraceLaunch launch) {
  const uint32_t total = ray_total(launch);
  const uint32_t lane = threadIdx.x % kWarp;
  for (;;) {
    uint32_t base = 0;
    if (lane == 0) base = atomicAdd(launch.next_ray, kWarp);
    base = __shfl_sync(0xFFFFFFFFu, base, 0);
    if (base >= total) return;
    if (base + lane < total) trace_slot(trace_one, launch, base + lane);
  }
}

unsigned int blocks(uint32_t count, uint32_t block) { return (count + block - 1) / block; }

// As many blocks of the persistent kernel as fit on the GPU at once (measured once per process).
template <typename TraceOne>
unsigned int resident_blocks() {
  static const unsigned int count = [] {
    int device = 0, multiprocessors = 0, per_multiprocessor = 0;
    GLINT_CUDA_CHECK(cudaGetDevice(&device));
    GLINT_CUDA_CHECK(cudaDeviceGetAttribute(&multiprocessors, cudaDevAttrMultiProcessorCount, device));
    GLINT_CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_multiprocessor, persistent_kernel<TraceOne>,
                                                                   static_cast<int>(kTraceBlock), 0));
    return static_cast<unsigned int>(multiprocessors * (per_multiprocessor > 0 ? per_multiprocessor : 1));
  }();
  return count;
}

template <typename TraceOne>
void launch_kernel(const TraceOne& trace_one, const TraceLaunch& launch, cudaStream_t stream) {
  if (launch.capacity == 0) return;
  if (launch.kernel == TraceKernel::persistent) {
    if (launch.next_ray == nullptr) fail_message("rt cuda: the persistent trace kernel needs a ray counter");
    GLINT_CUDA_CHECK(cudaMemsetAsync(launch.next_ray, 0, sizeof(uint32_t), stream));
    const unsigned int grid = std::min(resident_blocks<TraceOne>(), blocks(launch.capacity, kTraceBlock));
    persistent_kernel<<<grid, kTraceBlock, 0, stream>>>(trace_one, launch);
  } else {
    one_ray_per_thread_kernel<<<blocks(launch.capacity, kTraceBlock), kTraceBlock, 0, stream>>>(trace_one, launch);
  }
  GLINT_CUDA_CHECK_LAUNCH();
}

__global__ void __launch_bounds__(kTraceBlock)
    trace_closest_kdtree_kernel(accel::KdTreeView tree, accel::TriangleMesh mesh, const accel::Ray* rays,
                                accel::Hit* hits, uint32_t count) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < count) hits[i] = accel::trace_closest(tree, mesh, load_ray(rays, i));
}

// A BLAS's object-space root box (empty for an empty structure): a BVH's root node, a kd-tree's cell.
__device__ inline Aabb root_box(const accel::Blas& blas) {
  if (blas.bvh.node_count == 0) return Aabb{};
  const accel::BvhNode root = load_node(blas.bvh.nodes, 0);
  return {root.bounds_min, root.bounds_max};
}

__device__ inline Aabb root_box(const accel::KdBlas& blas) {
  return blas.tree.node_count == 0 ? Aabb{} : blas.tree.bounds;
}

template <typename BlasView>
__global__ void instance_boxes_kernel(const accel::Instance* instances, uint32_t count, const BlasView* blases,
                                      Aabb* boxes) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const accel::Instance& instance = instances[i];
  const Aabb root = root_box(blases[instance.blas]);
  Aabb world;
  if (!root.empty()) {
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 p((corner & 1) ? root.max.x : root.min.x, (corner & 2) ? root.max.y : root.min.y,
                   (corner & 4) ? root.max.z : root.min.z);
      world.extend(vec3(instance.object_to_world * vec4(p, 1.0f)));
    }
  }
  boxes[i] = world;
}

template <typename BlasView>
void launch_instance_boxes(const accel::Instance* instances, uint32_t instance_count, const BlasView* blases,
                           Aabb* boxes, cudaStream_t stream) {
  if (instance_count == 0) return;
  instance_boxes_kernel<<<blocks(instance_count, kBoxBlock), kBoxBlock, 0, stream>>>(instances, instance_count,
                                                                                      blases, boxes);
  GLINT_CUDA_CHECK_LAUNCH();
}

template <typename View>
void launch_any(const View& tlas, const TraceLaunch& launch, cudaStream_t stream) {
  if (launch.capacity != 0 && launch.occluded == nullptr)
    fail_message("rt cuda: an any-hit launch needs an occlusion buffer");
  launch_kernel(TwoLevelOcclusion<View>{tlas}, launch, stream);
}

}  // namespace

void launch_trace_closest(const accel::TlasView& tlas, const TraceLaunch& launch, cudaStream_t stream) {
  launch_kernel(TwoLevelTrace<accel::TlasView>{tlas}, launch, stream);
}

void launch_trace_any(const accel::TlasView& tlas, const TraceLaunch& launch, cudaStream_t stream) {
  launch_any(tlas, launch, stream);
}

void launch_trace_closest(const accel::KdTlasView& tlas, const TraceLaunch& launch, cudaStream_t stream) {
  launch_kernel(TwoLevelTrace<accel::KdTlasView>{tlas}, launch, stream);
}

void launch_trace_any(const accel::KdTlasView& tlas, const TraceLaunch& launch, cudaStream_t stream) {
  launch_any(tlas, launch, stream);
}

void launch_trace_closest(const accel::Blas& blas, const TraceLaunch& launch, cudaStream_t stream) {
  launch_kernel(SingleLevelTrace{blas}, launch, stream);
}

void launch_trace_closest(const accel::KdTreeView& tree, const accel::TriangleMesh& mesh, const accel::Ray* rays,
                          accel::Hit* hits, uint32_t count, cudaStream_t stream) {
  if (count == 0) return;
  trace_closest_kdtree_kernel<<<blocks(count, kTraceBlock), kTraceBlock, 0, stream>>>(tree, mesh, rays, hits, count);
  GLINT_CUDA_CHECK_LAUNCH();
}

void launch_instance_world_boxes(const accel::Instance* instances, uint32_t instance_count,
                                 const accel::Blas* blases, Aabb* boxes, cudaStream_t stream) {
  launch_instance_boxes(instances, instance_count, blases, boxes, stream);
}

void launch_instance_world_boxes(const accel::Instance* instances, uint32_t instance_count,
                                 const accel::KdBlas* blases, Aabb* boxes, cudaStream_t stream) {
  launch_instance_boxes(instances, instance_count, blases, boxes, stream);
}

}  // namespace glint::cuda
