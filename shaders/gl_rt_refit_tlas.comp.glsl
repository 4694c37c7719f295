#version 450 core
// The gl backend's GPU refit, top level (src/gl_rt/gl_refit.h, docs/ray-tracer.md "gl"), after the
// BLAS refit's dispatch: the TLAS the host built keeps its topology (the cuda backend's refit) and
// takes new boxes, one invocation per node. A leaf's box is the union of its instances' world boxes,
// each its BLAS's root box transformed by accel's rule (accel::instance_world_boxes, transform_aabb:
// the 8 corners through glm's mat4 * vec4, (c0 x + c1 y) + (c2 z + c3 w) with w = 1, bounded), with
// `precise` so that the compiler neither fuses nor reorders: the boxes equal the host's bit for bit.
// Then the climb (include/refit_climb.glsl); the TLAS's region starts at node 0.
layout(local_size_x = 64) in;

#include "include/refit_climb.glsl"

// gl_rt::GlInstanceRecord, as gl_rt_structures.glsl reads it (TracerInstance).
struct RefitInstance {
  mat4 world_to_object;
  uint node_offset;  // its BLAS's root in the node array
  uint slot_offset;
  uint node_count;   // 0: an empty BLAS, whose world box is empty
  uint unused;
};

layout(std430, binding = 21) readonly restrict buffer RefitTlasRefs { uint refit_tlas_refs[]; };
layout(std430, binding = 24) readonly restrict buffer RefitInstances { RefitInstance refit_instances[]; };
// Per instance its object-to-world transform (accel::Instance::object_to_world).
layout(std430, binding = 28) readonly restrict buffer RefitTransforms { mat4 refit_object_to_world[]; };

uniform uint tlas_node_count;

void main() {
  const uint node = grid_invocation();
  if (node >= tlas_node_count) return;
  const uint prim_count = refit_nodes[node].prim_count;
  if (prim_count == 0u) return;
  const uint first = refit_nodes[node].first;
  vec3 box_min, box_max;
  empty_box(box_min, box_max);
  for (uint slot = first; slot != first + prim_count; ++slot) {
    const uint instance = refit_tlas_refs[slot];
    const RefitInstance record = refit_instances[instance];
    if (record.node_count == 0u) continue;
    const vec3 root_min = refit_nodes[record.node_offset].bounds_min;
    const vec3 root_max = refit_nodes[record.node_offset].bounds_max;
    const mat4 m = refit_object_to_world[instance];
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 p = vec3((corner & 1) != 0 ? root_max.x : root_min.x, (corner & 2) != 0 ? root_max.y : root_min.y,
                          (corner & 4) != 0 ? root_max.z : root_min.z);
      // m[3] * 1 is m[3] exactly.
      precise vec3 world = (m[0].xyz * p.x + m[1].xyz * p.y) + (m[2].xyz * p.z + m[3].xyz);
      box_min = min(box_min, world);
      box_max = max(box_max, world);
    }
  }
  refit_from_leaf(0u, node, box_min, box_max);
}
