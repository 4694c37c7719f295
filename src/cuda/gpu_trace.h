#pragma once
// The closest-hit and any-hit (occlusion) kernels over a ray list in device memory (the CUDA
// backend's trace), and the instance boxes a GPU TLAS is built over. CUDA-only header: include it from .cu files.
#include "accel/kdtree/kdtree.h"
#include "accel/kdtree/kdtree_tlas.h"
#include "accel/ray.h"
#include "accel/tlas_traverse.h"
#include "cuda/trace_kernel.h"

#include <cuda_runtime.h>

#include <cstdint>

namespace glint::cuda {

// A launch over a ray list in device memory: for i < min(*ray_count, capacity) (ray_count may be
// null: then `capacity` rays), a closest-hit launch writes hits[i] = closest hit of rays[i], an
// any-hit launch occluded[i] = 1 when rays[i] hits anything within [t_min, t_max], else 0 (the other
// output pointer is unused and may be null). *overflow (device
// memory) is set to 1 when some ray's traversal stack overflowed (its hit may then be wrong).
// next_ray is a device counter the persistent kernel hands rays out with (zeroed by the launch;
// unused by the other kernel, may be null there).
struct TraceLaunch {
  const accel::Ray* rays = nullptr;
  accel::Hit* hits = nullptr;
  const uint32_t* ray_count = nullptr;
  uint32_t capacity = 0;
  uint32_t* overflow = nullptr;
  uint32_t* next_ray = nullptr;
  TraceKernel kernel = kDefaultTraceKernel;
  uint32_t* occluded = nullptr;  // last, so positional initialisers of closest-hit launches stay valid
};

// Through `tlas` (device views): Hit.instance is the instance index. Asynchronous on `stream`.
void launch_trace_closest(const accel::TlasView& tlas, const TraceLaunch& launch, cudaStream_t stream);

// The occlusion query through `tlas` into launch.occluded (the same kernels, the traversal in any-hit
// mode). Asynchronous on `stream`.
void launch_trace_any(const accel::TlasView& tlas, const TraceLaunch& launch, cudaStream_t stream);

// The same two queries through a TLAS whose BLASes are kd-trees (AccelOptions::blas = kdtree), in
// kernels of their own (the BVH kernels stay as they are).
void launch_trace_closest(const accel::KdTlasView& tlas, const TraceLaunch& launch, cudaStream_t stream);
void launch_trace_any(const accel::KdTlasView& tlas, const TraceLaunch& launch, cudaStream_t stream);

// shadow_rays[i] = rt::hit_shadow_ray of reflection ray i and its closest hit hits[i] (the hit
// triangle from `tlas`'s instances and meshes), towards `light`, for i < min(*ray_count, capacity)
// (ray_count may be null: `capacity`). Slots past the count are not written. Asynchronous on `stream`.
void launch_hit_shadow_rays(const accel::TlasView& tlas, const accel::Ray* rays, const accel::Hit* hits,
                            const uint32_t* ray_count, uint32_t capacity, vec3 light, float origin_offset,
                            accel::Ray* shadow_rays, cudaStream_t stream);
void launch_hit_shadow_rays(const accel::KdTlasView& tlas, const accel::Ray* rays, const accel::Hit* hits,
                            const uint32_t* ray_count, uint32_t capacity, vec3 light, float origin_offset,
                            accel::Ray* shadow_rays, cudaStream_t stream);

// Through one BLAS (a single-level structure, as accel-bench measures them): Hit.instance is 0.
void launch_trace_closest(const accel::Blas& blas, const TraceLaunch& launch, cudaStream_t stream);

// The same through a kd-tree (accel/kdtree/kdtree_traverse.h's front-to-back traversal, whose stack the
// builder's depth limit bounds) over one mesh: Hit.instance is 0.
void launch_trace_closest(const accel::KdTreeView& tree, const accel::TriangleMesh& mesh, const accel::Ray* rays,
                          accel::Hit* hits, uint32_t count, cudaStream_t stream);

// boxes[i] = world box of instance i: its BLAS's root box (blases[instances[i].blas].bvh.nodes[0],
// device memory) transformed by object_to_world; empty for an empty BLAS. Asynchronous on `stream`.
void launch_instance_world_boxes(const accel::Instance* instances, uint32_t instance_count,
                                 const accel::Blas* blases, Aabb* boxes, cudaStream_t stream);
// The same from kd-tree BLASes' root cells.
void launch_instance_world_boxes(const accel::Instance* instances, uint32_t instance_count,
                                 const accel::KdBlas* blases, Aabb* boxes, cudaStream_t stream);

}  // namespace glint::cuda
