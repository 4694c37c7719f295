#version 450 core
// The gl backend's GPU refit, bottom level (src/gl_rt/gl_refit.h, docs/ray-tracer.md "gl"): every
// dirty mesh's BLAS in one dispatch, one invocation per node. A leaf's box is the min and max of its
// triangles' object-space vertices (accel::refit's, exactly: min and max do not round), read through
// the leaf slots as the traces read them; then the climb (include/refit_climb.glsl). The meshes'
// climbs run side by side, so the dispatch takes the deepest one's time, not their sum.
layout(local_size_x = 64) in;

#include "include/refit_climb.glsl"

layout(std430, binding = 22) readonly restrict buffer RefitVertices { vec4 refit_vertices[]; };
layout(std430, binding = 23) readonly restrict buffer RefitLeafTriangles { uvec4 refit_leaf_triangles[]; };
// One per BLAS of the dispatch, by ascending w: x its region's first node, y its node count (> 0),
// z its first leaf slot, w the dispatch's first invocation of it (the previous ones' node counts
// summed), so the BLASes' invocations follow each other without a gap.
layout(std430, binding = 27) readonly restrict buffer RefitJobs { uvec4 refit_jobs[]; };

uniform uint job_count;         // > 0
uniform uint invocation_count;  // the node counts summed

void main() {
  const uint invocation = grid_invocation();
  if (invocation >= invocation_count) return;
  // The last job starting at or before this invocation: thousands of meshes take a dozen steps.
  uint low = 0u, high = job_count - 1u;
  while (low < high) {
    const uint middle = (low + high + 1u) / 2u;
    if (refit_jobs[middle].w <= invocation) low = middle;
    else high = middle - 1u;
  }
  const uvec4 job = refit_jobs[low];
  const uint base = job.x, node = invocation - job.w;
  const uint prim_count = refit_nodes[base + node].prim_count;
  if (prim_count == 0u) return;  // an interior node: its children's invocations climb to it
  const uint first = job.z + refit_nodes[base + node].first;
  vec3 box_min, box_max;
  empty_box(box_min, box_max);
  for (uint slot = first; slot != first + prim_count; ++slot) {
    const uvec4 triangle = refit_leaf_triangles[slot];
    for (int corner = 0; corner < 3; ++corner) {
      const vec3 p = refit_vertices[triangle[corner]].xyz;
      box_min = min(box_min, p);
      box_max = max(box_max, p);
    }
  }
  refit_from_leaf(base, node, box_min, box_max);
}
