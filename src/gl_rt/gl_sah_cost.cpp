#include "gl_rt/gl_sah_cost.h"

#include "gl/compute_grid.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl_rt/gl_rt_bindings.h"

#include <algorithm>

namespace glint::gl_rt {
GlSahCost::GlSahCost()
    : program_(ShaderProgram::from_embedded({"gl_rt_sah_cost.comp.glsl"})),
      job_count_(program_.uniform_location("job_count")),
      node_cost_(program_.uniform_location("node_cost")),
      prim_cost_(program_.uniform_location("prim_cost")) {
  // The shader's layout(local_size_x) is the one place the work-group size is set.
  GLint size[3] = {0, 0, 0};
  glGetProgramiv(program_.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
  group_size_ = static_cast<GLuint>(size[0]);
}

void GlSahCost::measure(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes,
                        const accel::SahCosts& costs, GLuint out) {
  if (meshes.empty()) return;
  GlPassScope scope("accel_sah");
  job_scratch_.clear();
  for (const std::uint32_t mesh : meshes) {
    const GlStructureBuffers::BlasRegion& region = structures.region(mesh);
    job_scratch_.emplace_back(region.node_offset, region.node_count, 0u, 0u);
  }
  structures.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSahJobBinding, jobs_.hold(job_scratch_));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSahCostBinding, out);
  glProgramUniform1ui(program_.id(), job_count_, static_cast<GLuint>(meshes.size()));
  glProgramUniform1f(program_.id(), node_cost_, costs.node);
  glProgramUniform1f(program_.id(), prim_cost_, costs.prim);
  program_.use();
  // One work group per BLAS, in a grid (gl/compute_grid.h) so that no number of meshes is too many.
  const ComputeGrid grid = grid_of_work_groups(std::uint64_t{group_size_} * meshes.size(), group_size_,
                                               "rt gl: SAH cost (a work group per BLAS)");
  glDispatchCompute(grid.columns, grid.rows, 1);
  // The costs are copied (a readback ring) or read back.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl("rt gl: SAH cost");
}

std::vector<double> GlSahCost::measure_now(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes,
                                           const accel::SahCosts& costs) {
  std::vector<double> result(meshes.size());
  if (meshes.empty()) return result;
  if (meshes.size() > scratch_capacity_) {
    scratch_capacity_ = std::max(meshes.size(), 2 * scratch_capacity_);
    scratch_ = create_buffer(scratch_capacity_ * sizeof(double), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  measure(structures, meshes, costs, scratch_.id());
  glGetNamedBufferSubData(scratch_.id(), 0, static_cast<GLsizeiptr>(result.size() * sizeof(double)), result.data());
  check_gl("rt gl: reading the SAH costs back");
  return result;
}

}  // namespace glint::gl_rt
