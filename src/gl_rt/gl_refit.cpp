#include "gl_rt/gl_refit.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl_rt/gl_rt_bindings.h"

#include <algorithm>

namespace glint::gl_rt {
namespace {

constexpr GLuint kGroupSize = 64;            // the kernels' local_size_x
constexpr std::uint64_t kMaxGroups = 65535;  // per dimension, GL's guaranteed minimum

// One invocation per item, in a grid of at most kMaxGroups x kMaxGroups work groups (refit_invocation()
// in shaders/include/refit_climb.glsl unfolds it), so no scene is too large for one dispatch.
void dispatch_over(std::uint64_t items) {
  const std::uint64_t groups = (items + kGroupSize - 1) / kGroupSize;
  if (groups == 0) return;
  const std::uint64_t columns = std::min(groups, kMaxGroups);
  const std::uint64_t rows = (groups + columns - 1) / columns;
  if (rows > kMaxGroups) fail("rt gl: {} BVH nodes to refit in one dispatch, more than GL's grid holds", items);
  glDispatchCompute(static_cast<GLuint>(columns), static_cast<GLuint>(rows), 1);
}

}  // namespace

GlRefit::GlRefit()
    : blas_(ShaderProgram::from_embedded({"gl_rt_refit_blas.comp.glsl"})),
      tlas_(ShaderProgram::from_embedded({"gl_rt_refit_tlas.comp.glsl"})),
      job_count_(blas_.uniform_location("job_count")),
      invocation_count_(blas_.uniform_location("invocation_count")),
      tlas_node_count_(tlas_.uniform_location("tlas_node_count")) {}

void GlRefit::refit(const GlStructureBuffers& structures, std::span<const std::uint32_t> meshes) {
  GlPassScope scope("accel_refit");
  // Jobs in the order given; each BLAS's invocations follow the previous one's.
  job_scratch_.clear();
  std::uint64_t invocations = 0;
  for (const std::uint32_t mesh : meshes) {
    const GlStructureBuffers::BlasRegion& region = structures.region(mesh);
    if (region.node_count == 0) continue;
    job_scratch_.emplace_back(region.node_offset, region.node_count, region.slot_offset,
                              static_cast<std::uint32_t>(invocations));
    invocations += region.node_count;
  }
  // Node counts sum below 2^32: they all live in one node array of 32-bit indices.
  structures.bind_for_refit();
  if (!job_scratch_.empty()) {
    if (job_scratch_ != jobs_in_buffer_) {
      if (job_scratch_.size() > job_capacity_) {
        job_capacity_ = std::max(job_scratch_.size(), 2 * job_capacity_);
        jobs_ = create_buffer(job_capacity_ * sizeof(glm::uvec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
      }
      glNamedBufferSubData(jobs_.id(), 0, static_cast<GLsizeiptr>(job_scratch_.size() * sizeof(glm::uvec4)),
                           job_scratch_.data());
      jobs_in_buffer_ = job_scratch_;
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRefitJobBinding, jobs_.id());
    glProgramUniform1ui(blas_.id(), job_count_, static_cast<GLuint>(job_scratch_.size()));
    glProgramUniform1ui(blas_.id(), invocation_count_, static_cast<GLuint>(invocations));
    blas_.use();
    dispatch_over(invocations);
    // The TLAS's leaves read the BLASes' root boxes.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glProgramUniform1ui(tlas_.id(), tlas_node_count_, structures.tlas_node_count());
  tlas_.use();
  dispatch_over(structures.tlas_node_count());
  // The traces read the nodes through their buffer texture (texelFetch) and the rest as storage; a
  // host update or a test writes or reads the buffers (buffer update).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("rt gl: GPU refit");
}

}  // namespace glint::gl_rt
