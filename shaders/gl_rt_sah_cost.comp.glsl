#version 450 core
// The gl backend's SAH cost of BLASes as they are in the node array (src/gl_rt/gl_sah_cost.h,
// docs/ray-tracer.md "gl"): what the automatic update policy compares with the cost right after a
// BLAS's last build. The host's definition, accel::compute_stats (src/accel/bvh_stats.cpp): the
// interior nodes' half areas and the leaves' half areas times their primitive counts, each area a
// float (accel::half_area), summed in double, weighted by the traversal and intersection costs and
// divided by the root's half area (by 1 where that is 0). The areas are computed operation for
// operation as the host's, under `precise`, so they are the same floats; only the order of the double
// sums differs, so the cost agrees with the host's to double rounding.
// One work group per BLAS (few deforming meshes, each of thousands of nodes): its invocations stride
// over the BVH's nodes, then a tree reduction in shared memory. 1024 invocations, GL's guaranteed
// most, so that a BLAS of 100k nodes takes about 100 dependent steps per invocation (16 KiB of shared
// doubles, half GL's guaranteed 32 KiB).
layout(local_size_x = 1024) in;

#include "include/gl_rt_structures.glsl"
#include "include/grid_invocation.glsl"

// Per job: x its BVH's first node in the node array, y its node count (0: an empty BLAS, cost 0).
layout(std430, binding = 27) readonly restrict buffer SahJobs { uvec4 sah_jobs[]; };
layout(std430, binding = 26) writeonly restrict buffer SahCosts { double sah_costs[]; };

uniform uint job_count;
uniform float node_cost;  // accel::BuildOptions::traversal_cost
uniform float prim_cost;  // accel::BuildOptions::intersection_cost

shared double interior_sums[gl_WorkGroupSize.x];
shared double leaf_sums[gl_WorkGroupSize.x];

// accel::half_area: 0 for an empty box, else e.x e.y + e.y e.z + e.z e.x in float, left to right.
float half_area(vec3 low, vec3 high) {
  if (any(greaterThan(low, high))) return 0.0;
  precise vec3 e = high - low;
  precise float area = e.x * e.y + e.y * e.z + e.z * e.x;
  return area;
}

void main() {
  // Whole work groups per job (the grid's columns are groups), so a group returns or stays together
  // and reaches the barriers below in uniform control flow.
  const uint job = grid_invocation() / gl_WorkGroupSize.x;
  if (job >= job_count) return;
  const uint local = gl_LocalInvocationID.x;
  const uvec4 region = sah_jobs[job];
  double interior = 0.0lf, leaves = 0.0lf;
  for (uint i = local; i < region.y; i += gl_WorkGroupSize.x) {
    const BvhNode node = load_node(region.x + i);
    const double area = double(half_area(node.bounds_min, node.bounds_max));
    if (node.prim_count != 0u) leaves += area * double(node.prim_count);
    else interior += area;
  }
  interior_sums[local] = interior;
  leaf_sums[local] = leaves;
  memoryBarrierShared();
  barrier();
  for (uint stride = gl_WorkGroupSize.x / 2u; stride > 0u; stride /= 2u) {
    if (local < stride) {
      interior_sums[local] += interior_sums[local + stride];
      leaf_sums[local] += leaf_sums[local + stride];
    }
    memoryBarrierShared();
    barrier();
  }
  if (local != 0u) return;
  if (region.y == 0u) {
    sah_costs[job] = 0.0lf;
    return;
  }
  const BvhNode root = load_node(region.x);
  const double root_area = double(half_area(root.bounds_min, root.bounds_max));
  const double normaliser = root_area > 0.0lf ? root_area : 1.0lf;
  sah_costs[job] = (double(node_cost) * interior_sums[0] + double(prim_cost) * leaf_sums[0]) / normaliser;
}
