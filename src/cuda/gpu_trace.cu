#include "cuda/gpu_trace.h"

#include "cuda/cuda_check.h"
#include "accel/kdtree_traverse.h"
#include "cuda/gpu_traverse.cuh"

namespace glint::cuda {
namespace {

// 128 threads: traversal keeps two 64-entry stacks per thread in local memory, and smaller blocks
// measured no slower while leaving the scheduler more freedom (docs/perf.md, CUDA backend).
constexpr uint32_t kTraceBlock = 128;
constexpr uint32_t kBoxBlock = 128;

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

__global__ void __launch_bounds__(kTraceBlock)
    trace_closest_kernel(accel::TlasView tlas, const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                         uint32_t capacity, uint32_t* overflow) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  const uint32_t count = ray_count ? min(*ray_count, capacity) : capacity;
  if (i >= count) return;
  bool overflowed = false;
  hits[i] = gpu_trace_closest(tlas, load_ray(rays, i), overflowed);
  if (overflowed) atomicOr(overflow, 1u);
}

__global__ void __launch_bounds__(kTraceBlock)
    trace_closest_single_kernel(accel::Blas blas, const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                                uint32_t capacity, uint32_t* overflow) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  const uint32_t count = ray_count ? min(*ray_count, capacity) : capacity;
  if (i >= count) return;
  const accel::Ray ray = load_ray(rays, i);
  accel::Hit hit;
  float t_max = ray.t_max;
  bool overflowed = false;
  if (gpu_intersect_closest(blas, ray.origin, ray.direction, ray.t_min, t_max, hit, overflowed)) hit.instance = 0;
  hits[i] = hit;
  if (overflowed) atomicOr(overflow, 1u);
}

__global__ void __launch_bounds__(kTraceBlock)
    trace_closest_kdtree_kernel(accel::KdTreeView tree, accel::TriangleMesh mesh, const accel::Ray* rays,
                                accel::Hit* hits, uint32_t count) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < count) hits[i] = accel::trace_closest(tree, mesh, load_ray(rays, i));
}

__global__ void instance_boxes_kernel(const accel::Instance* instances, uint32_t count, const accel::Blas* blases,
                                      Aabb* boxes) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const accel::Instance& instance = instances[i];
  const accel::BvhView& bvh = blases[instance.blas].bvh;
  Aabb world;
  if (bvh.node_count != 0) {
    const accel::BvhNode root = load_node(bvh.nodes, 0);
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 p((corner & 1) ? root.bounds_max.x : root.bounds_min.x,
                   (corner & 2) ? root.bounds_max.y : root.bounds_min.y,
                   (corner & 4) ? root.bounds_max.z : root.bounds_min.z);
      world.extend(vec3(instance.object_to_world * vec4(p, 1.0f)));
    }
  }
  boxes[i] = world;
}

unsigned int blocks(uint32_t count, uint32_t block) { return (count + block - 1) / block; }

}  // namespace

void launch_trace_closest(const accel::TlasView& tlas, const accel::Ray* rays, accel::Hit* hits,
                          const uint32_t* ray_count, uint32_t capacity, uint32_t* overflow, cudaStream_t stream) {
  if (capacity == 0) return;
  trace_closest_kernel<<<blocks(capacity, kTraceBlock), kTraceBlock, 0, stream>>>(tlas, rays, hits, ray_count,
                                                                                  capacity, overflow);
  GLINT_CUDA_CHECK_LAUNCH();
}

void launch_trace_closest(const accel::Blas& blas, const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                          uint32_t capacity, uint32_t* overflow, cudaStream_t stream) {
  if (capacity == 0) return;
  trace_closest_single_kernel<<<blocks(capacity, kTraceBlock), kTraceBlock, 0, stream>>>(blas, rays, hits, ray_count,
                                                                                         capacity, overflow);
  GLINT_CUDA_CHECK_LAUNCH();
}

void launch_trace_closest(const accel::KdTreeView& tree, const accel::TriangleMesh& mesh, const accel::Ray* rays,
                          accel::Hit* hits, uint32_t count, cudaStream_t stream) {
  if (count == 0) return;
  trace_closest_kdtree_kernel<<<blocks(count, kTraceBlock), kTraceBlock, 0, stream>>>(tree, mesh, rays, hits, count);
  GLINT_CUDA_CHECK_LAUNCH();
}

void launch_instance_world_boxes(const accel::Instance* instances, uint32_t instance_count,
                                 const accel::Blas* blases, Aabb* boxes, cudaStream_t stream) {
  if (instance_count == 0) return;
  instance_boxes_kernel<<<blocks(instance_count, kBoxBlock), kBoxBlock, 0, stream>>>(instances, instance_count,
                                                                                      blases, boxes);
  GLINT_CUDA_CHECK_LAUNCH();
}

}  // namespace glint::cuda
