#pragma once
// One OptiX GAS over one triangle mesh with the closest-hit query, for accel-bench's optix rows
// (src/app/accel_bench/candidates_optix.h): the same single-level setting as glint's own builders
// there, hits with instance 0 (a GAS traced without an instance). Build and refit times are wall
// clock from the first enqueue to the GPU finishing, synchronous, so they include launch overheads
// and, for optix-fasttrace, compaction with its host readback of the compacted size; the trace time
// is the launch's GPU time.
// Plain C++ (no OptiX or CUDA headers); built only with GLINT_HAVE_OPTIX.
#include "accel/ray.h"
#include "accel/triangle_mesh.h"
#include "optix/build_preference.h"

#include <cstddef>
#include <memory>
#include <span>

namespace glint::optix {

class OptixMeshTracer {
public:
  // Creates the OptiX context and pipeline; glint::Error (one line) without a GPU or a usable OptiX.
  explicit OptixMeshTracer(BuildPreference preference);
  ~OptixMeshTracer();
  OptixMeshTracer(const OptixMeshTracer&) = delete;
  OptixMeshTracer& operator=(const OptixMeshTracer&) = delete;

  // Uploads `mesh` (not timed) and builds its GAS; returns the build's milliseconds.
  double build(const accel::TriangleMesh& mesh);
  // Uploads the moved vertices of `mesh` (same triangles as the last build; not timed) and updates
  // the GAS in place (OPTIX_BUILD_OPERATION_UPDATE); returns the update's milliseconds. The first
  // refit after a build first rebuilds (untimed) with ALLOW_UPDATE, which the traced build lacks.
  double refit(const accel::TriangleMesh& mesh);
  // hits[i] = closest hit of rays[i] (instance 0); waits for the GPU and returns the launch's GPU
  // time in ms (the rays' upload and the hits' download excluded, like the cuda rows).
  double trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits);
  // The GAS's device memory (output buffer, compacted for optix-fasttrace).
  std::size_t structure_bytes() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace glint::optix
