// The gl backend's two-level walk, one invocation per ray: src/accel/tlas_traverse.h over the TLAS
// and src/accel/traverse.h in each BLAS entered (depth first, the nearer child first, the farther one
// pushed and skipped on pop once a closer hit is known; the conservative slab test; the watertight
// triangle test; accel::record_closer_hit's tie rule), so hits equal the cpu backend's up to rounding.
// Each level descends to a leaf before it visits the leaf's contents ("while-while"): on an H100 the
// gl backend's hybrid frame took 1.70 ms against 1.75 with one step per loop (docs/perf.md, "Tenth
// round"); the CUDA walk in that form was slower, and keeps one step per loop.
// Two entry points: trace_closest() and trace_occluded() (the occlusion query, which returns at the
// first hit). Both are one walk whose `any_hit` argument is a literal at each call, so a compiler,
// which inlines GLSL's functions, compiles each query's own walk as the constant it was before (the
// closest-hit kernel traced 0.46 ms against 0.47 with the includer's constant on an H100). A shader
// should call one of them only: the two walks in one kernel (a reflection trace that also traced its
// hits' shadow rays) took twice as long as two kernels, written out apart or not (docs/perf.md
// "Eleventh round").
// A render pass that includes this file traces inline: rt::GlTracing::bind_inline_tracing binds the
// structures and sets tlas_node_count on its program.
#include "include/accel_records.glsl"
#include "include/gl_rt_structures.glsl"
#include "include/gl_rt_triangle.glsl"

const uint kInvalidIndex = 0xFFFFFFFFu;
// accel::kMaxBvhDepth: a push past it sets tracer_stack_overflow (gl_rt_structures.glsl) and ends that
// level's walk instead of writing past the stack. glint's builders never get there.
const uint kStackSize = 64u;
// The slab test's slack on its far distance. accel::kSlabFarScale is 1 + 2 gamma(3) = 1 + 3 ulp: each
// slab distance takes three roundings of at most u = 2^-24 (a subtraction, the inverse, a product).
// GLSL's division may be off by 2.5 ulp = 5 u (GLSL 4.50, 4.7.1), so each distance here is within
// gamma(7) and the slack is 1 + 8 ulp >= 1 + 2 gamma(7): more slack only visits a few more boxes,
// never changes a hit.
const float kSlabFarScale = uintBitsToFloat(0x3F800008u);

struct BoxRay {
  vec3 origin;
  vec3 inv_direction;  // +-infinity for a zero component; its sign picks the near plane
};

BoxRay make_box_ray(vec3 origin, vec3 direction) {
  precise vec3 inv_direction = vec3(1.0) / direction;
  return BoxRay(origin, inv_direction);
}

// accel::intersect_box: the segment [t_min, t_max] enters the node's box; t_entry is where (clamped
// to t_min). The comparisons are written so that a NaN (0 x infinity) never wins, as on the CPU.
bool intersect_box(BoxRay ray, BvhNode node, float t_min, float t_max, out float t_entry) {
  const bvec3 negative = lessThan(ray.inv_direction, vec3(0.0));
  const vec3 near_plane = mix(node.bounds_min, node.bounds_max, negative);
  const vec3 far_plane = mix(node.bounds_max, node.bounds_min, negative);
  precise vec3 t0 = (near_plane - ray.origin) * ray.inv_direction;
  precise vec3 t1 = (far_plane - ray.origin) * ray.inv_direction;
  float t_near = t_min;
  t_near = t0.x > t_near ? t0.x : t_near;
  t_near = t0.y > t_near ? t0.y : t_near;
  t_near = t0.z > t_near ? t0.z : t_near;
  float t_far = kInfinity;
  t_far = t1.x < t_far ? t1.x : t_far;
  t_far = t1.y < t_far ? t1.y : t_far;
  t_far = t1.z < t_far ? t1.z : t_far;
  precise float t_exit = (t_far < t_max ? t_far : t_max) * kSlabFarScale;
  t_entry = t_near;
  return t_near <= t_exit;
}

// The step at an interior node (its children at node_offset + first and the one after), shared by
// both levels: returns how many children the segment enters. 1: `next` is that child; 2: `next` is
// the nearer one and far_index the other one's node, to be pushed.
uint enter_children(BvhNode node, uint node_offset, BoxRay ray, float t_min, float t_max, const bool any_hit,
                    out BvhNode next, out uint far_index) {
  const uint left_index = node_offset + node.first;
  const BvhNode left = load_node(left_index);
  const BvhNode right = load_node(left_index + 1u);
  float t_left, t_right;
  const bool hit_left = intersect_box(ray, left, t_min, t_max, t_left);
  const bool hit_right = intersect_box(ray, right, t_min, t_max, t_right);
  // The nearer child first, where the order can matter: the occlusion query stops at any hit, so it
  // skips the comparison and walks left first (shadow rays 4 % faster on the H200, 2026-11-26).
  const bool right_first = hit_right && (!hit_left || (!any_hit && t_right < t_left));
  next = right_first ? right : left;
  far_index = right_first ? left_index : left_index + 1u;
  return uint(hit_left) + uint(hit_right);
}

// Per-invocation stacks (globals are private to each invocation), one per level, of node indices
// only. The CUDA kernel also stacks each node's entry distance, to skip it on pop once t_max fell
// below it; here the popped node's box is tested again with the t_max of then, which skips exactly
// the same nodes (the entry distance comes out bit for bit the same, and it was at most the box's
// exit when pushed) for a box test instead of a second stack array. A stack of entry distances made
// the closest-hit trace 0.49 ms against 0.37 and the occlusion query 1.0 ms against 0.50 on an
// H100 (docs/perf.md "Ninth round").
uint tlas_stack_node[kStackSize];
uint blas_stack_node[kStackSize];

// The next subtree of the enclosing walk's level that may still hold something closer than t_max
// (with the box test's slack), popped from `stack` into `node`; returns `found` from the walk when the
// stack is empty. The occlusion query returns at its first hit, so its t_max never falls: every
// pushed node passes, untested. A macro rather than a function: the same loop as a function with an
// `out` node made the gl backend's hybrid frame 1.80 ms against 1.71 on an H100 (docs/perf.md,
// "Tenth round").
#define POP_OR_RETURN(stack)                                                  \
  for (;;) {                                                                  \
    if (stack_size == 0u) return found;                                       \
    --stack_size;                                                             \
    node = load_node(stack[stack_size]);                                      \
    float entry;                                                              \
    if (any_hit || intersect_box(box_ray, node, t_min, t_max, entry)) break;  \
  }

// One BLAS in the instance's object space. Closest hit: records a closer hit in `hit` (t, prim, u, v),
// lowering t_max; returns whether it did. Any hit: returns true at the first triangle in range.
bool walk_blas(TracerInstance instance, vec3 origin, vec3 direction, float t_min, inout float t_max,
               const bool any_hit, inout Hit hit) {
  if (instance.node_count == 0u) return false;
  const BoxRay box_ray = make_box_ray(origin, direction);
  BvhNode node = load_node(instance.node_offset);
  float t_entry;
  if (!intersect_box(box_ray, node, t_min, t_max, t_entry)) return false;
  const WatertightRay ray = make_watertight_ray(origin, direction);
  uint stack_size = 0u;
  bool found = false;
  for (;;) {
    // Interior nodes until a leaf, then its triangles ("while-while", Aila & Laine 2009): a warp's
    // invocations reach their leaves before any of them tests a triangle, so the triangle tests run
    // side by side instead of one invocation's leaf holding up the others' descent.
    while (node.prim_count == 0u) {
      BvhNode next;
      uint far_index;
      const uint entered =
          enter_children(node, instance.node_offset, box_ray, t_min, t_max, any_hit, next, far_index);
      if (entered == 2u) {
        if (stack_size == kStackSize) {
          tracer_stack_overflow = 1u;
          return found;
        }
        blas_stack_node[stack_size] = far_index;
        ++stack_size;
      }
      if (entered != 0u) {
        node = next;
        continue;
      }
      POP_OR_RETURN(blas_stack_node)
    }
    const uint end = node.first + node.prim_count;
    for (uint slot = node.first; slot != end; ++slot) {
      const uvec4 corners = leaf_triangles[instance.slot_offset + slot];
      const uint prim = corners.w;
      float t, u, v;
      if (!intersect_triangle(ray, mesh_vertices[corners.x].xyz, mesh_vertices[corners.y].xyz,
                              mesh_vertices[corners.z].xyz, t_min, t_max, t, u, v))
        continue;
      if (any_hit) return true;
      // accel::record_closer_hit: equal t keeps the hit found first (in this or an earlier instance).
      if (t == t_max && hit.prim != kInvalidIndex) continue;
      t_max = t;
      hit.t = t;
      hit.prim = prim;
      hit.u = u;
      hit.v = v;
      found = true;
    }
    POP_OR_RETURN(blas_stack_node)
  }
  return found;
}

// Both levels for one world ray: the TLAS over instances (the region at the start of the node array,
// its leaves in tlas_refs), each instance entered with the ray in its object space (accel::to_object_space: glm's
// mat4 x vec4 as (c0 x + c1 y) + (c2 z + c3 w), so t is the same in both spaces). Closest hit: `hit`
// in RayTracer's convention (Hit{t = inf, instance = prim = kInvalidIndex} for a miss). Any hit:
// returns whether anything lies within [t_min, t_max].
bool trace_ray(vec3 origin, vec3 direction, float t_min, float ray_t_max, const bool any_hit, out Hit hit) {
  hit = Hit(kInfinity, kInvalidIndex, kInvalidIndex, 0.0, 0.0);
  if (tlas_node_count == 0u) return false;
  float t_max = ray_t_max;
  const BoxRay box_ray = make_box_ray(origin, direction);
  BvhNode node = load_node(0u);
  float t_entry;
  if (!intersect_box(box_ray, node, t_min, t_max, t_entry)) return false;
  uint stack_size = 0u;
  bool found = false;
  for (;;) {
    // Interior nodes until a leaf, then its instances, as in walk_blas: here the warp's invocations
    // enter their BLAS walks together.
    while (node.prim_count == 0u) {
      BvhNode next;
      uint far_index;
      const uint entered = enter_children(node, 0u, box_ray, t_min, t_max, any_hit, next, far_index);
      if (entered == 2u) {
        if (stack_size == kStackSize) {
          tracer_stack_overflow = 1u;
          return found;
        }
        tlas_stack_node[stack_size] = far_index;
        ++stack_size;
      }
      if (entered != 0u) {
        node = next;
        continue;
      }
      POP_OR_RETURN(tlas_stack_node)
    }
    const uint end = node.first + node.prim_count;
    for (uint slot = node.first; slot != end; ++slot) {
      const uint index = tlas_refs[slot];
      const TracerInstance instance = tracer_instances[index];
      const mat4 m = instance.world_to_object;
      precise vec3 local_origin = (m[0].xyz * origin.x + m[1].xyz * origin.y) + (m[2].xyz * origin.z + m[3].xyz);
      // w = 0: c3 w is a zero added to c2 z, which leaves it unchanged.
      precise vec3 local_direction = (m[0].xyz * direction.x + m[1].xyz * direction.y) + m[2].xyz * direction.z;
      if (!walk_blas(instance, local_origin, local_direction, t_min, t_max, any_hit, hit)) continue;
      if (any_hit) return true;
      hit.instance = index;
      found = true;
    }
    POP_OR_RETURN(tlas_stack_node)
  }
  return found;
}

// The closest hit of the ray within [t_min, t_max], in RayTracer's convention (Hit{t = inf, instance =
// prim = kInvalidIndex} for a miss).
Hit trace_closest(vec3 origin, vec3 direction, float t_min, float t_max) {
  Hit hit;
  trace_ray(origin, direction, t_min, t_max, false, hit);
  return hit;
}

// The occlusion query: whether anything lies within [t_min, t_max] (the walk returns at the first
// hit, the nearer child not sought).
bool trace_occluded(vec3 origin, vec3 direction, float t_min, float t_max) {
  Hit unused;
  return trace_ray(origin, direction, t_min, t_max, true, unused);
}
