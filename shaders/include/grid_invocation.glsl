// The invocation index of a 1D kernel dispatched as a grid of work groups (src/gl/compute_grid.h,
// grid_of_work_groups: columns x rows groups of local_size_x, columns filled first), so that no
// count is too large for one dispatch for want of groups in one dimension (65,535). Indices run
// row by row; the last row may run past the count, so a kernel compares the index with it.
uint grid_invocation() {
  return gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
}
