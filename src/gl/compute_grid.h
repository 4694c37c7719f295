#pragma once
// A compute dispatch of N invocations of a 1D kernel as a grid of work groups: one dimension alone
// stops at 65,535 groups (GL's guaranteed minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT: 4.2 million
// invocations in groups of 64), so the groups are laid out as columns x rows, columns filled first,
// and the shader recovers its invocation index with grid_invocation()
// (shaders/include/grid_invocation.glsl); invocations from N up to the grid's end return early.
// Users: gl_rt/gl_refit.cpp and render/gl_scene_deformer.cpp (gl_rt/gl_sah_cost.cpp reads the limit).
// It lives in gl/ rather than with the image passes' sizes in render/compute_dispatch.h because gl_rt/
// may not include render/: render/ includes backends/, which includes gl_rt/, and the folders' includes must have no cycle
// (tests/architecture/folder_dependencies_test.cpp).
#include "core/error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <string_view>

namespace glint {

// Work groups per grid dimension: GL's guaranteed minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT.
inline constexpr std::uint64_t kMaxComputeGroupsPerDimension = 65535;

// A dispatch's work groups: glDispatchCompute(columns, rows, 1); 0 x 0 for no invocations.
struct ComputeGrid {
  GLuint columns = 0;
  GLuint rows = 0;
  bool operator==(const ComputeGrid&) const = default;
};

// The grid of `invocations` invocations in work groups of `group_size` (the kernel's local_size_x):
// as many columns as needed up to 65,535, then as many rows. glint::Error, naming `what` (the
// dispatch, e.g. "rt gl: BLAS refit"), where the rows pass 65,535 too, or where the grid's
// invocation indices would pass 2^32 (grid_invocation() counts in uint: they would wrap onto
// earlier invocations).
inline ComputeGrid grid_of_work_groups(std::uint64_t invocations, GLuint group_size, std::string_view what) {
  if (group_size == 0) fail("{}: a dispatch in work groups of 0 invocations", what);
  const std::uint64_t groups = invocations / group_size + (invocations % group_size != 0 ? 1 : 0);
  if (groups == 0) return {};
  const std::uint64_t columns = std::min(groups, kMaxComputeGroupsPerDimension);
  const std::uint64_t rows = (groups + columns - 1) / columns;
  if (rows > kMaxComputeGroupsPerDimension)
    fail("{}: {} invocations in one dispatch need {} work groups of {}, more than GL's 65,535 x 65,535 grid holds",
         what, invocations, groups, group_size);
  // columns * rows * group_size > 2^32, without overflowing 64 bits.
  if (columns * rows > (std::uint64_t{1} << 32) / group_size)
    fail("{}: {} invocations in one dispatch need a grid of {} x {} work groups of {}, whose invocation indices pass "
         "2^32 (the shader counts them in uint)",
         what, invocations, columns, rows, group_size);
  return {static_cast<GLuint>(columns), static_cast<GLuint>(rows)};
}

}  // namespace glint
