#pragma once
// One single-level structure on the GPU, for accel-bench's `--backend cuda` rows: a mesh of world
// triangles, its BVH built on the GPU (lbvh, ploc) or on the CPU and uploaded (every other builder
// of the menu), refitted on the GPU, and traced by the CUDA kernel the cuda backend uses.
//
// What the times measure (GPU times from CUDA events unless said otherwise), chosen to match what a
// frame of the renderer pays, where vertices, rays and hits already live on the GPU:
//  - build: GPU builders: triangle boxes + build, the mesh already uploaded; CPU builders: the CPU
//    build's wall time plus the upload of the BVH.
//  - refit: one launch that boxes the leaves from the triangles and refits bottom-up (the frame's
//    refit_meshes_gpu), the moved vertices already uploaded.
//  - trace: the closest-hit kernel alone (the rays' upload and the hits' download excluded).
// Plain C++ (no CUDA headers); without CUDA or a GPU the constructor throws glint::Error.
#include "accel/builders/build_options.h"
#include "accel/builders/builder.h"
#include "accel/bvh.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"
#include "cuda/trace_kernel.h"

#include <memory>
#include <optional>
#include <span>

namespace glint::cuda {

class GpuBenchStructure {
public:
  // `kernel`: which closest-hit kernel traces (cuda/trace_kernel.h).
  explicit GpuBenchStructure(accel::BvhBuilder builder, const accel::BuildOptions& options = {},
                             TraceKernel kernel = kDefaultTraceKernel);
  ~GpuBenchStructure();
  GpuBenchStructure(const GpuBenchStructure&) = delete;
  GpuBenchStructure& operator=(const GpuBenchStructure&) = delete;

  // Uploads `mesh` and builds over it; returns the build time in ms (see above).
  double build(const accel::TriangleMesh& mesh);
  // Uploads the moved vertices (same triangles) and refits; returns ms, or nullopt when the structure
  // cannot be refitted (sbvh).
  std::optional<double> refit(const accel::TriangleMesh& mesh);
  // hits[i] = closest hit of rays[i]; returns the kernel's time in ms.
  double trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits);
  // The structure, downloaded (node count, SAH, validation).
  accel::Bvh download() const;
  std::size_t memory_bytes() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace glint::cuda
