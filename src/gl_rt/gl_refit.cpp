#include "gl_rt/gl_refit.h"

#include "gl/compute_grid.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl_rt/gl_rt_bindings.h"

#include <string_view>

namespace glint::gl_rt {
namespace {

constexpr GLuint kGroupSize = 64;  // the kernels' local_size_x

// One invocation per item, in a grid of up to 65,535 x 65,535 work groups (gl/compute_grid.h;
// grid_invocation() in shaders/include/grid_invocation.glsl unfolds it), so no scene is too large for
// one dispatch. `what` names the dispatch in the error where it does not fit.
void dispatch_over(std::uint64_t items, std::string_view what) {
  const ComputeGrid grid = grid_of_work_groups(items, kGroupSize, what);
  if (grid.columns == 0) return;
  glDispatchCompute(grid.columns, grid.rows, 1);
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
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRefitJobBinding, jobs_.hold(job_scratch_));
    glProgramUniform1ui(blas_.id(), job_count_, static_cast<GLuint>(job_scratch_.size()));
    glProgramUniform1ui(blas_.id(), invocation_count_, static_cast<GLuint>(invocations));
    blas_.use();
    dispatch_over(invocations, "rt gl: BLAS refit (one invocation per BVH node)");
    // The TLAS's leaves read the BLASes' root boxes.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  glProgramUniform1ui(tlas_.id(), tlas_node_count_, structures.tlas_node_count());
  tlas_.use();
  dispatch_over(structures.tlas_node_count(), "rt gl: TLAS refit (one invocation per BVH node)");
  // The traces read the nodes through their buffer texture (texelFetch) and the rest as storage; a
  // host update or a test writes or reads the buffers (buffer update).
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  check_gl("rt gl: GPU refit");
}

}  // namespace glint::gl_rt
