#pragma once
// The gl backend's structures refitted on the GPU (GlRayTracer::update_gl, docs/ray-tracer.md "gl"):
// after a GL-side deformer wrote new positions into the vertex buffer, two compute dispatches bring
// the boxes up to date with no host refit and no upload. First every dirty mesh's BLAS in one
// dispatch (shaders/gl_rt_refit_blas.comp.glsl: leaves from their triangles' vertices, then a climb
// to the root by arrival counters through the parent links the host wrote with the layout, the
// algorithm of cuda/gpu_bvh_refit.cu), then the TLAS with the topology the host built
// (gl_rt_refit_tlas.comp.glsl: leaves from their instances' world boxes by accel's rule, the same
// climb). Min and max do not round, so the BLAS boxes equal accel::refit's over the same vertices,
// and the world boxes are computed operation for operation as accel's, so the TLAS's equal
// accel::refit_tlas's.
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "gl_rt/gl_job_buffer.h"
#include "gl_rt/gl_structure_buffers.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::gl_rt {

class GlRefit {
public:
  // Compiles the two kernels on the current GL context.
  GlRefit();

  // Enqueues the refit of the BLASes of `meshes` (distinct, in range, refittable; empty ones are
  // skipped) and then of the TLAS, and the barriers after which the traces (the nodes through their
  // buffer texture, the rest as storage) and buffer reads and writes see the new boxes. The positions
  // must already be visible to shaders (written by a copy, or by a shader followed by its barrier).
  void refit(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes);

private:
  ShaderProgram blas_;
  ShaderProgram tlas_;
  GLint job_count_ = -1, invocation_count_ = -1, tlas_node_count_ = -1;
  GlJobBuffer jobs_;  // the BLAS dispatch's jobs (refit_jobs)
  std::vector<glm::uvec4> job_scratch_;
};

}  // namespace glint::gl_rt
