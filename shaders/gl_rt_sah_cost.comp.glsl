#version 450 core
// The gl backend's SAH cost of BLASes as they are in the node array (src/gl_rt/gl_sah_cost.h,
// docs/ray-tracer.md "gl"): what the automatic update policy compares with the cost right after a
// BLAS's last build. The host's definition, accel::compute_stats (src/accel/bvh_stats.cpp): the
// interior nodes' half areas and the leaves' half areas times their primitive counts, each area a
// float (accel::half_area), summed in double, weighted by the traversal and intersection costs and
// divided by the root's half area (by 1 where that is 0). The areas are computed operation for
// operation as the host's, under `precise`, so they are the same floats; only the order of the double
// sums differs, so the cost agrees with the host's to double rounding.
// Two stages, a dispatch each, so that the sums spread over the GPU: one work group per BVH, its
// invocations looping over a hundred nodes each, took 0.037 ms of the deforming atrium's frame on an
// H100 (the `accel_sah` scope; 0.016 ms now: docs/perf.md "Thirteenth round").
//   stage 0  work group (g, j): nodes [g, g + 1) x nodes_per_invocation x the local size of job j's
//            BLAS, summed in shared memory into sah_partials[j * groups_per_job + g]
//   stage 1  work group (0, j): job j's partial sums, its cost
layout(local_size_x = 256) in;

#include "include/gl_rt_structures.glsl"

// Per job: x its BVH's first node in the node array, y its node count (0: an empty BLAS, cost 0).
layout(std430, binding = 27) readonly restrict buffer SahJobs { uvec4 sah_jobs[]; };
layout(std430, binding = 26) writeonly restrict buffer SahCosts { double sah_costs[]; };
// Per job and stage-0 work group: {interior half areas, leaf half areas x primitives}.
layout(std430, binding = 25) restrict buffer SahPartials { dvec2 sah_partials[]; };

uniform uint stage;
uniform uint nodes_per_invocation;  // stage 0 (GlSahCost::kNodesPerInvocation)
uniform uint groups_per_job;  // stage 0's work groups per job: enough for the largest BLAS
uniform float node_cost;      // accel::BuildOptions::traversal_cost
uniform float prim_cost;      // accel::BuildOptions::intersection_cost

shared dvec2 sums[gl_WorkGroupSize.x];

// accel::half_area: 0 for an empty box, else e.x e.y + e.y e.z + e.z e.x in float, left to right.
float half_area(vec3 low, vec3 high) {
  if (any(greaterThan(low, high))) return 0.0;
  precise vec3 e = high - low;
  precise float area = e.x * e.y + e.y * e.z + e.z * e.x;
  return area;
}

// The work group's sum of every invocation's `value` (all invocations call it).
dvec2 group_sum(dvec2 value) {
  const uint local = gl_LocalInvocationID.x;
  sums[local] = value;
  memoryBarrierShared();
  barrier();
  for (uint stride = gl_WorkGroupSize.x / 2u; stride > 0u; stride /= 2u) {
    if (local < stride) sums[local] += sums[local + stride];
    memoryBarrierShared();
    barrier();
  }
  return sums[0];
}

void main() {
  // Whole work groups per job and partial (the grid's rows are jobs), so a group stays together and
  // reaches group_sum's barriers in uniform control flow.
  const uint job = gl_WorkGroupID.y;
  const uint local = gl_LocalInvocationID.x;
  const uvec4 region = sah_jobs[job];
  if (stage == 0u) {
    dvec2 sum = dvec2(0.0lf);
    const uint first = gl_WorkGroupID.x * nodes_per_invocation * gl_WorkGroupSize.x + local;
    for (uint k = 0u; k < nodes_per_invocation; ++k) {
      const uint i = first + k * gl_WorkGroupSize.x;
      if (i >= region.y) break;
      const BvhNode node = load_node(region.x + i);
      const double area = double(half_area(node.bounds_min, node.bounds_max));
      if (node.prim_count != 0u) sum.y += area * double(node.prim_count);
      else sum.x += area;
    }
    sum = group_sum(sum);
    if (local == 0u) sah_partials[job * groups_per_job + gl_WorkGroupID.x] = sum;
    return;
  }
  dvec2 sum = dvec2(0.0lf);
  for (uint g = local; g < groups_per_job; g += gl_WorkGroupSize.x) sum += sah_partials[job * groups_per_job + g];
  sum = group_sum(sum);
  if (local != 0u) return;
  if (region.y == 0u) {
    sah_costs[job] = 0.0lf;
    return;
  }
  const BvhNode root = load_node(region.x);
  const double root_area = double(half_area(root.bounds_min, root.bounds_max));
  const double normaliser = root_area > 0.0lf ? root_area : 1.0lf;
  sah_costs[job] = (double(node_cost) * sum.x + double(prim_cost) * sum.y) / normaliser;
}
