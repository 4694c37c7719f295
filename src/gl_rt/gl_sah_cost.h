#pragma once
// The SAH cost of the gl backend's BLASes measured where their boxes are, in the GL node array
// (shaders/gl_rt_sah_cost.comp.glsl): after a GPU refit only the GPU has the boxes, and the automatic
// update policy and RayTracerStats::blas_sah_drift compare that cost with the one right after the
// BLAS's last build. The same definition and constants as the host's (accel::compute_stats with
// AccelOptions::build's traversal and intersection costs), so a host cost of the same boxes agrees to
// double rounding (the float areas are the same; only the order of the double sums differs).
#include "accel/bvh_stats.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "gl_rt/gl_job_buffer.h"
#include "gl_rt/gl_structure_buffers.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::gl_rt {

class GlSahCost {
public:
  // Compiles the kernel on the current GL context.
  GlSahCost();

  // Enqueues the cost of each BLAS of `meshes` (in range; an empty one costs 0) into `costs`, a buffer
  // of at least meshes.size() doubles, one per entry in order, and the barrier after which buffer
  // reads and copies see them. Binds the structures (GlStructureBuffers::bind) and the program.
  void measure(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes,
               const accel::SahCosts& costs, GLuint out);

  // The same, read back at once (the host waits for the GPU): for stats() and tests, not for a frame.
  std::vector<double> measure_now(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes,
                                  const accel::SahCosts& costs);

  // Nodes each invocation of the shader's first stage sums: few, so that a BVH spreads over many work
  // groups (docs/ray-tracer.md "gl").
  static constexpr GLuint kNodesPerInvocation = 4;

private:
  ShaderProgram program_;
  GLint stage_ = -1, nodes_per_invocation_ = -1, groups_per_job_ = -1, node_cost_ = -1, prim_cost_ = -1;
  GLuint group_size_ = 0;  // the kernel's local_size_x
  GlBuffer partials_;      // per job and stage-0 work group: two doubles
  std::size_t partials_capacity_ = 0;  // dvec2s
  GlJobBuffer jobs_;
  std::vector<glm::uvec4> job_scratch_;
  GlBuffer scratch_;  // measure_now's costs, grown as needed
  std::size_t scratch_capacity_ = 0;
};

}  // namespace glint::gl_rt
