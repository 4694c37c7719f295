#pragma once
// Internal: the wide BVH traversal kernel, one template over the SIMD interface of wide_bvh_simd.h.
// Included by exactly one translation unit per instruction set, which first defines
// GLINT_WIDE_KERNEL_ATTR: empty for SSE, __attribute__((target("avx2"))) for AVX2. Every function
// here carries it (and no lambdas, which would not), so the AVX2 instances are compiled for AVX2
// while the rest of the library stays baseline x86-64 and runs on any CPU.
//
// Per ray: the box test of all N children of a node at once (Ize's conservative slab test, as in
// intersect_box.h), hit children sorted near to far onto a stack of (child, entry distance); the
// nearest is visited next and the others are skipped on pop once a closer hit shrank t_max. A leaf
// tests its triangle blocks N at a time with the watertight test of intersect_triangle.h, same
// operations in the same order, so t, u, v are bit-identical to the scalar traversal's.
#ifndef GLINT_WIDE_KERNEL_ATTR
#error "define GLINT_WIDE_KERNEL_ATTR before including accel/wide/wide_bvh_kernel.h"
#endif

#include "accel/bvh_node.h"
#include "accel/intersect_box.h"
#include "accel/intersect_triangle.h"
#include "accel/ray.h"
#include "accel/wide/wide_bvh.h"
#include "accel/wide/wide_bvh_simd.h"

#include <cstddef>
#include <cstdint>

namespace glint::accel::wide_kernel {

// Everything about a ray the kernel reuses at every node and leaf, broadcast to all lanes.
template <class S>
struct SimdRay {
  using F = typename S::F;
  F origin[3];
  F inv_direction[3];
  F t_min;
  // Float offsets into WideNode::bounds of each axis' near and far planes: the near plane is the
  // min for a direction component >= +0 and the max otherwise (same choice as intersect_box).
  int near_offset[3], far_offset[3];
  // Watertight test: origin along the permuted axes and the shear constants.
  int kx, ky, kz;
  F origin_kx, origin_ky, origin_kz;
  F shear_x, shear_y, shear_z;
};

template <class S>
GLINT_WIDE_KERNEL_ATTR inline SimdRay<S> make_simd_ray(const Ray& ray) {
  SimdRay<S> r;
  const BoxRay box_ray = make_box_ray(ray.origin, ray.direction);
  for (int axis = 0; axis < 3; ++axis) {
    r.origin[axis] = S::set1(ray.origin[axis]);
    r.inv_direction[axis] = S::set1(box_ray.inv_direction[axis]);
    const int near_side = box_ray.inv_direction[axis] < 0.0f ? 1 : 0;
    r.near_offset[axis] = (2 * axis + near_side) * S::kWidth;
    r.far_offset[axis] = (2 * axis + 1 - near_side) * S::kWidth;
  }
  r.t_min = S::set1(ray.t_min);
  const WatertightRay woop = make_watertight_ray(ray.origin, ray.direction);
  const float origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  r.kx = woop.kx;
  r.ky = woop.ky;
  r.kz = woop.kz;
  r.origin_kx = S::set1(origin[woop.kx]);
  r.origin_ky = S::set1(origin[woop.ky]);
  r.origin_kz = S::set1(origin[woop.kz]);
  r.shear_x = S::set1(woop.shear_x);
  r.shear_y = S::set1(woop.shear_y);
  r.shear_z = S::set1(woop.shear_z);
  return r;
}

// Slab test of the N children; returns the lane mask of the boxes the segment [t_min, t_max]
// enters and their entry distances in `entry`.
template <class S, int N>
GLINT_WIDE_KERNEL_ATTR inline unsigned intersect_children(const WideNode<N>& node, const SimdRay<S>& r, float t_max,
                                                          float* entry) {
  using F = typename S::F;
  F t_near = r.t_min;
  F t_far = S::set1(kInfinity);
  const float* planes = &node.bounds[0][0][0];
  for (int axis = 0; axis < 3; ++axis) {
    const F near_plane = S::load(planes + r.near_offset[axis]);
    const F far_plane = S::load(planes + r.far_offset[axis]);
    // max/min keep their second operand on NaN (0 * infinity on a plane): that axis is ignored.
    t_near = S::max(S::mul(S::sub(near_plane, r.origin[axis]), r.inv_direction[axis]), t_near);
    t_far = S::min(S::mul(S::sub(far_plane, r.origin[axis]), r.inv_direction[axis]), t_far);
  }
  t_far = S::mul(S::min(t_far, S::set1(t_max)), S::set1(kSlabFarScale));
  S::store(entry, t_near);
  return S::mask(S::le(t_near, t_far));
}

// Edge values that came out exactly 0 are recomputed in double, as the scalar test does. A template
// over S like everything here, so the SSE and AVX2 files never define one function differently.
template <class S>
GLINT_WIDE_KERNEL_ATTR inline float exact_edge(float a, float b, float c, float d) {
  return static_cast<float>(static_cast<double>(a) * b - static_cast<double>(c) * d);
}

// Watertight test of the `lanes` of one block; returns the lanes hit within [t_min, t_max] and
// their t, u, v.
template <class S, int N>
GLINT_WIDE_KERNEL_ATTR inline unsigned intersect_block(const TriangleBlock<N>& block, unsigned lanes,
                                                       const SimdRay<S>& r, float t_min, float t_max, float* t_out,
                                                       float* u_out, float* v_out) {
  using F = typename S::F;
  const F akz = S::sub(S::load(block.v[0][r.kz]), r.origin_kz);
  const F bkz = S::sub(S::load(block.v[1][r.kz]), r.origin_kz);
  const F ckz = S::sub(S::load(block.v[2][r.kz]), r.origin_kz);
  const F ax = S::sub(S::sub(S::load(block.v[0][r.kx]), r.origin_kx), S::mul(r.shear_x, akz));
  const F ay = S::sub(S::sub(S::load(block.v[0][r.ky]), r.origin_ky), S::mul(r.shear_y, akz));
  const F bx = S::sub(S::sub(S::load(block.v[1][r.kx]), r.origin_kx), S::mul(r.shear_x, bkz));
  const F by = S::sub(S::sub(S::load(block.v[1][r.ky]), r.origin_ky), S::mul(r.shear_y, bkz));
  const F cx = S::sub(S::sub(S::load(block.v[2][r.kx]), r.origin_kx), S::mul(r.shear_x, ckz));
  const F cy = S::sub(S::sub(S::load(block.v[2][r.ky]), r.origin_ky), S::mul(r.shear_y, ckz));

  F e0 = S::sub(S::mul(cx, by), S::mul(cy, bx));
  F e1 = S::sub(S::mul(ax, cy), S::mul(ay, cx));
  F e2 = S::sub(S::mul(bx, ay), S::mul(by, ax));
  const F zero = S::set1(0.0f);
  const unsigned on_edge = S::mask(S::bit_or(S::bit_or(S::eq(e0, zero), S::eq(e1, zero)), S::eq(e2, zero))) & lanes;
  if (on_edge != 0) {  // rare: a ray through an edge or a vertex
    alignas(32) float sax[N], say[N], sbx[N], sby[N], scx[N], scy[N], se0[N], se1[N], se2[N];
    S::store(sax, ax), S::store(say, ay), S::store(sbx, bx), S::store(sby, by), S::store(scx, cx), S::store(scy, cy);
    S::store(se0, e0), S::store(se1, e1), S::store(se2, e2);
    for (int lane = 0; lane < N; ++lane) {
      if ((on_edge >> lane & 1u) == 0) continue;
      se0[lane] = exact_edge<S>(scx[lane], sby[lane], scy[lane], sbx[lane]);
      se1[lane] = exact_edge<S>(sax[lane], scy[lane], say[lane], scx[lane]);
      se2[lane] = exact_edge<S>(sbx[lane], say[lane], sby[lane], sax[lane]);
    }
    e0 = S::load(se0), e1 = S::load(se1), e2 = S::load(se2);
  }
  const unsigned negative = S::mask(S::bit_or(S::bit_or(S::lt(e0, zero), S::lt(e1, zero)), S::lt(e2, zero)));
  const unsigned positive = S::mask(S::bit_or(S::bit_or(S::gt(e0, zero), S::gt(e1, zero)), S::gt(e2, zero)));
  const F det = S::add(S::add(e0, e1), e2);
  unsigned hit = lanes & ~(negative & positive) & ~S::mask(S::eq(det, zero));
  if (hit == 0) return 0;

  const F az = S::mul(r.shear_z, akz);
  const F bz = S::mul(r.shear_z, bkz);
  const F cz = S::mul(r.shear_z, ckz);
  const F scaled_t = S::add(S::add(S::mul(e0, az), S::mul(e1, bz)), S::mul(e2, cz));
  const F inv_det = S::div(S::set1(1.0f), det);
  const F t = S::mul(scaled_t, inv_det);
  hit &= S::mask(S::bit_and(S::bit_and(S::ge(t, S::set1(t_min)), S::le(t, S::set1(t_max))),
                            S::lt(t, S::set1(kInfinity))));
  if (hit == 0) return 0;
  S::store(t_out, t);
  S::store(u_out, S::mul(e1, inv_det));
  S::store(v_out, S::mul(e2, inv_det));
  return hit;
}

struct StackEntry {
  uint32_t child;
  uint32_t prim_count;  // 0: interior node
  float entry;
};

// Each level leaves at most N - 1 entries behind, and the wide depth is at most kMaxBvhDepth.
template <int N>
inline constexpr int kStackSize = static_cast<int>(kMaxBvhDepth) * (N - 1) + N;

// Closest hit (kAnyHit false: `hit` receives t, prim, u, v) or any hit (returns at the first).
template <class S, int N, bool kAnyHit>
GLINT_WIDE_KERNEL_ATTR inline bool traverse(const WideBvh<N>& bvh, const Ray& ray, Hit& hit) {
  static_assert(S::kWidth == N);
  if (bvh.nodes.empty()) return false;
  const WideNode<N>* nodes = bvh.nodes.data();
  const TriangleBlock<N>* blocks = bvh.blocks.data();
  const SimdRay<S> r = make_simd_ray<S>(ray);
  const float t_min = ray.t_min;
  float t_max = ray.t_max;
  bool found = false;

  StackEntry stack[kStackSize<N>];
  int stack_size = 0;
  StackEntry current{0, 0, t_min};
  for (;;) {
    if (current.prim_count == 0) {
      alignas(32) float entry[N];
      const WideNode<N>& node = nodes[current.child];
      unsigned mask = intersect_children<S, N>(node, r, t_max, entry);
      if (mask != 0) {
        const int first = __builtin_ctz(mask);
        mask &= mask - 1;
        if (mask == 0) {
          current = {node.child[first], node.prim_count[first], entry[first]};
          continue;
        }
        // Several children: push them all, sort that segment far to near (insertion sort of at
        // most N), then take the nearest back off the top.
        const int base = stack_size;
        stack[stack_size++] = {node.child[first], node.prim_count[first], entry[first]};
        do {
          const int lane = __builtin_ctz(mask);
          mask &= mask - 1;
          StackEntry pushed{node.child[lane], node.prim_count[lane], entry[lane]};
          int i = stack_size++;
          if constexpr (!kAnyHit) {
            for (; i > base && stack[i - 1].entry < pushed.entry; --i) stack[i] = stack[i - 1];
          }
          stack[i] = pushed;
        } while (mask != 0);
        current = stack[--stack_size];
        continue;
      }
    } else {
      const uint32_t block_end = current.child + wide_block_count<N>(current.prim_count);
      uint32_t remaining = current.prim_count;  // wraps after the last block, which ends the loop
      for (uint32_t b = current.child; b != block_end; ++b, remaining -= N) {
        const unsigned lanes = remaining >= static_cast<uint32_t>(N) ? (1u << N) - 1u : (1u << remaining) - 1u;
        alignas(32) float t[N], u[N], v[N];
        unsigned mask = intersect_block<S, N>(blocks[b], lanes, r, t_min, t_max, t, u, v);
        if (mask == 0) continue;
        if constexpr (kAnyHit) return true;
        // Lanes in order, keeping the first of equal t, exactly as the scalar loop would.
        do {
          const int lane = __builtin_ctz(mask);
          mask &= mask - 1;
          if (t[lane] < t_max || (t[lane] == t_max && !found)) {
            t_max = t[lane];
            hit.t = t[lane];
            hit.prim = blocks[b].prim[lane];
            hit.u = u[lane];
            hit.v = v[lane];
            found = true;
          }
        } while (mask != 0);
      }
    }
    // Pop the next subtree that may still hold something closer than t_max (with the box slack).
    for (;;) {
      if (stack_size == 0) return found;
      current = stack[--stack_size];
      if (current.entry <= t_max * kSlabFarScale) break;
    }
  }
}

template <class S, int N>
GLINT_WIDE_KERNEL_ATTR void trace_closest_range(const WideBvh<N>& bvh, const Ray* rays, Hit* hits, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    Hit hit;
    if (traverse<S, N, false>(bvh, rays[i], hit)) hit.instance = 0;
    hits[i] = hit;
  }
}

template <class S, int N>
GLINT_WIDE_KERNEL_ATTR void trace_any_range(const WideBvh<N>& bvh, const Ray* rays, uint8_t* occluded, size_t count) {
  for (size_t i = 0; i < count; ++i) {
    Hit unused;
    occluded[i] = traverse<S, N, true>(bvh, rays[i], unused) ? 1 : 0;
  }
}

}  // namespace glint::accel::wide_kernel
