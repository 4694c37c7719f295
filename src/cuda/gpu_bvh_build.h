#pragma once
// GPU BVH construction over primitive boxes that already live in device memory (triangle boxes for
// a BLAS, instance world boxes for a TLAS) and refit (a BLAS's leaves boxed from its triangles, a
// TLAS's from the instance boxes), so a deforming mesh is rebuilt or refitted every frame without a
// host round trip. The output is a GpuBvh in accel::BvhNode's flat layout (children after their
// parent, siblings adjacent), so accel/traverse.h walks it unchanged and a downloaded copy passes
// accel::validate_bvh.
//
// Everything here is asynchronous on the given stream: calls enqueue work and return; once the
// builder's scratch and the output are large enough, a rebuild allocates nothing.
// CUDA-only header: include it from .cu files.
#include "accel/builders/build_options.h"
#include "accel/triangle_mesh.h"
#include "cuda/gpu_bvh.h"
#include "cuda/gpu_bvh_host.h"  // GpuBvhBuilder, gpu_builder_name

#include <cstdint>
#include <memory>
#include <span>

namespace glint::cuda {

// One builder with its scratch memory, kept between builds (one per structure rebuilt per frame).
class GpuBvhBuild {
public:
  // options.ploc_radius is used by ploc; leaves hold one primitive.
  explicit GpuBvhBuild(GpuBvhBuilder builder, const accel::BuildOptions& options = {});
  ~GpuBvhBuild();
  GpuBvhBuild(GpuBvhBuild&&) noexcept;
  GpuBvhBuild& operator=(GpuBvhBuild&&) noexcept;

  // Builds `out` (nodes, prim_indices, parents; refittable) over prim_boxes[0, count) on `stream`.
  // count == 0 gives an empty BVH; count must be below 2^31. out.depth is set to a bound known on
  // the host, never above accel::kMaxBvhDepth (lbvh: 62, from the key bits; ploc: kMaxBvhDepth,
  // which its iteration loop enforces; both at most count); the exact depth is measure_depth()'s.
  // ploc reads a cluster count back after each of its iterations, so it waits for the stream.
  void build(const Aabb* prim_boxes, uint32_t count, GpuBvh& out, cudaStream_t stream);

  GpuBvhBuilder builder() const;

private:
  struct Scratch;
  GpuBvhBuilder builder_;
  accel::BuildOptions options_;
  std::unique_ptr<Scratch> scratch_;
};

// boxes[i] = bounds of mesh.triangle(i) for every triangle (device memory on both sides): a BLAS
// build's input (a BLAS refit boxes its leaves from the triangles itself, refit_meshes_gpu).
void compute_triangle_boxes(const accel::TriangleMesh& device_mesh, Aabb* boxes, cudaStream_t stream);

// Bottom-up box update after the primitives moved (same count, same topology): every leaf's box from
// prim_boxes, every interior box from its children, through bvh.parents and one atomic counter per
// node (`counters`, kept with the BVH: zeroed when their count changes, left at 0 by each refit).
// The TLAS's refit over its instance boxes; refit_meshes_gpu's kernel with one BVH.
void refit_gpu(GpuBvh& bvh, const Aabb* prim_boxes, DeviceBuffer<uint32_t>& counters, cudaStream_t stream);

// A BLAS refitted from its mesh's triangles (device memory), with its counters as in refit_gpu.
struct MeshRefit {
  GpuBvh* bvh = nullptr;
  accel::TriangleMesh mesh;
  DeviceBuffer<uint32_t>* counters = nullptr;
};

// refit_gpu of several BLASes in one launch, each leaf's box computed from its triangles (no box
// array): the boxes equal refit_gpu's over compute_triangle_boxes bit for bit. The climbs of all
// the meshes run side by side, where one refit_gpu after another would wait for each one's depth.
void refit_meshes_gpu(std::span<const MeshRefit> refits, cudaStream_t stream);

// The tree's depth (levels, root = 1), computed on the GPU and read back (waits for the stream).
uint32_t measure_depth(const GpuBvh& bvh, cudaStream_t stream);

}  // namespace glint::cuda
