#include "gl_rt/gl_sah_cost.h"

#include "core/error.h"
#include "gl/compute_grid.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl_rt/gl_rt_bindings.h"

#include <algorithm>

namespace glint::gl_rt {
GlSahCost::GlSahCost()
    : program_(ShaderProgram::from_embedded({"gl_rt_sah_cost.comp.glsl"})),
      stage_(program_.uniform_location("stage")),
      nodes_per_invocation_(program_.uniform_location("nodes_per_invocation")),
      groups_per_job_(program_.uniform_location("groups_per_job")),
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
  std::uint64_t most_nodes = 0;
  for (const std::uint32_t mesh : meshes) {
    const GlStructureBuffers::BlasRegion& region = structures.region(mesh);
    job_scratch_.emplace_back(region.node_offset, region.node_count, 0u, 0u);
    most_nodes = std::max<std::uint64_t>(most_nodes, region.node_count);
  }
  // Stage 0's grid: a row per job, as many columns as the largest BLAS needs (a smaller one's extra
  // groups add zeros); stage 1's: a work group per row.
  const std::uint64_t nodes_per_group = std::uint64_t{kNodesPerInvocation} * group_size_;
  const std::uint64_t groups_per_job = std::max<std::uint64_t>(1, (most_nodes + nodes_per_group - 1) / nodes_per_group);
  if (groups_per_job > kMaxComputeGroupsPerDimension || meshes.size() > kMaxComputeGroupsPerDimension)
    fail("rt gl: SAH cost of {} BLASes of up to {} nodes: at most {} BLASes of {} nodes each can be measured",
         meshes.size(), most_nodes, kMaxComputeGroupsPerDimension, kMaxComputeGroupsPerDimension * nodes_per_group);
  const std::size_t partials = static_cast<std::size_t>(groups_per_job) * meshes.size();
  if (partials > partials_capacity_) {
    partials_capacity_ = std::max(partials, 2 * partials_capacity_);
    partials_ = create_buffer(partials_capacity_ * 2 * sizeof(double), nullptr, 0);
  }
  structures.bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSahJobBinding, jobs_.hold(job_scratch_));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSahPartialBinding, partials_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSahCostBinding, out);
  glProgramUniform1ui(program_.id(), nodes_per_invocation_, kNodesPerInvocation);
  glProgramUniform1ui(program_.id(), groups_per_job_, static_cast<GLuint>(groups_per_job));
  glProgramUniform1f(program_.id(), node_cost_, costs.node);
  glProgramUniform1f(program_.id(), prim_cost_, costs.prim);
  program_.use();
  const auto jobs = static_cast<GLuint>(meshes.size());
  glProgramUniform1ui(program_.id(), stage_, 0u);
  glDispatchCompute(static_cast<GLuint>(groups_per_job), jobs, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);  // stage 1 reads the partial sums
  glProgramUniform1ui(program_.id(), stage_, 1u);
  glDispatchCompute(1, jobs, 1);
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
