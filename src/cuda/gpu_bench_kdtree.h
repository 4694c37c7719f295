#pragma once
// The SAH kd-tree on the GPU, for accel-bench's `cuda-kdtree` row: built on the CPU
// (accel::build_kdtree, Wald & Havran 2006), uploaded in its 8-byte node layout, and traced by a CUDA
// kernel running accel/kdtree/kdtree_traverse.h's front-to-back traversal (the OptiX 3/4 TriangleKdTree of
// the paper's menu, on glint's GPU path). Not refittable (split references). Times as in
// gpu_bench_structure.h: build = CPU build + upload, trace = the kernel alone.
// Plain C++ (no CUDA headers); without CUDA or a GPU the constructor throws glint::Error.
#include "accel/kdtree/kdtree.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <memory>
#include <span>

namespace glint::cuda {

class GpuBenchKdTree {
public:
  GpuBenchKdTree();
  ~GpuBenchKdTree();
  GpuBenchKdTree(const GpuBenchKdTree&) = delete;
  GpuBenchKdTree& operator=(const GpuBenchKdTree&) = delete;

  // Uploads `mesh`, builds the tree on the CPU and uploads it; returns the build + upload ms.
  double build(const accel::TriangleMesh& mesh);
  // hits[i] = closest hit of rays[i]; returns the kernel's GPU time in ms.
  double trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits);
  // The tree as built on the CPU (stats).
  const accel::KdTree& tree() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace glint::cuda
