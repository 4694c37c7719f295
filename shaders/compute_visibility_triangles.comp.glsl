#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, per triangle (ComputeVisibilityPass, both rounds): one invocation per
// triangle of every instance, numbered in draw order (instance after instance, each mesh's
// triangles in index order: what the id draw's gl_PrimitiveID counts). It culls triangles outside
// one frustum plane and those covering no pixel centre, rasterises a small one itself, and in round
// 0 leaves the others (large, or to be clipped) to compute_visibility_large.comp.glsl through the
// deferred list. 32-bit arithmetic only: the rare cases' clipping and 64-bit edge functions live in
// their own dispatch, where they cost this one nothing (on llvmpipe they made it ten times slower).
layout(local_size_x = 64) in;

#include "include/frame_constants.glsl"
#include "include/scene_geometry.glsl"
#include "include/scene_instances.glsl"
#include "include/compute_visibility_buffers.glsl"
#include "include/compute_raster.glsl"

uniform uint triangle_count;
#ifndef GLINT_RASTER_ONE_ROUND  // the stamps tell round 1 what to redo: one round has none
uniform uint run_stamp;  // differs from every earlier run's
#endif

// A triangle is small when one invocation tests at most kSmallTriangleMaxPixels candidate centres
// (its pixel box): the pixels a thread walks bound how long its warp waits, whatever the scene's
// scale or the resolution. Its corners must also lie within kSmallTriangleSide pixels of each other,
// which keeps its edge functions exact in 32 bits (2 x (64 x 256)^2 = 2^29).
const int kSmallTriangleMaxPixels = 64;
const int kSmallTriangleSide = 64;

void defer(uint triangle) {
  if (raster_round != 0u) return;  // the list made in round 0 serves round 1
  const uint slot = atomicAdd(deferred_count, 1u);
  deferred[slot] = triangle;
  if (slot % kDeferredGroupSize == 0u && slot / kDeferredGroupSize < kMaxGroupsX) atomicAdd(deferred_dispatch[0], 1u);
}

void main() {
  const uint triangle =
      (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
  if (triangle >= triangle_count) return;
#ifndef GLINT_RASTER_ONE_ROUND
  // Round 1 redoes only the small triangles round 0 found nearest somewhere (most are culled or
  // hidden): a triangle nearer than all others at a pixel was nearer than what it read there.
  if (raster_round != 0u && touched[triangle] != run_stamp) return;
#endif
  vec4 p[3];
  fetch_triangle(triangle, p);
  if ((outcode(p[0]) & outcode(p[1]) & outcode(p[2])) != 0u) return;
  if (needs_clipping(p[0]) || needs_clipping(p[1]) || needs_clipping(p[2])) {
    defer(triangle);
    return;
  }
  ivec2 a = snap_to_window(p[0]), b = snap_to_window(p[1]), c = snap_to_window(p[2]);
  const ivec2 lo = min(a, min(b, c)), hi = max(a, max(b, c));
  const ivec4 box = pixel_box(lo, hi);
  if (box_empty(box)) return;
  const ivec2 span = box.zw - box.xy + 1;
  if (any(greaterThan(hi - lo, ivec2(kSmallTriangleSide * kSubpixelOne))) || span.x * span.y > kSmallTriangleMaxPixels) {
    defer(triangle);
    return;
  }

  // Corners relative to the first centre: every value below stays within 2^30.
  const ivec2 origin = box.xy * kSubpixelOne + kHalfPixel;
  a -= origin;
  b -= origin;
  c -= origin;
  vec3 z = vec3(window_depth(p[0]), window_depth(p[1]), window_depth(p[2]));
  int area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (area == 0) return;
  if (area < 0) {  // both faces are drawn: turn it counter-clockwise
    const ivec2 t = b;
    b = c;
    c = t;
    z = z.xzy;
    area = -area;
  }
  // Edge values E(u, v, p) = (v - u).x (p - u).y - (v - u).y (p - u).x at the first centre (p = 0)
  // and their change per pixel; the same integers raster_pixel computes in 64 bits.
  int row_a = (c.y - b.y) * b.x - (c.x - b.x) * b.y;
  int row_b = (a.y - c.y) * c.x - (a.x - c.x) * c.y;
  int row_c = (b.y - a.y) * a.x - (b.x - a.x) * a.y;
  const ivec2 step_a = ivec2(b.y - c.y, c.x - b.x) * kSubpixelOne;
  const ivec2 step_b = ivec2(c.y - a.y, a.x - c.x) * kSubpixelOne;
  const ivec2 step_c = ivec2(a.y - b.y, b.x - a.x) * kSubpixelOne;
  const int bias_a = fill_bias(b, c), bias_b = fill_bias(c, a), bias_c = fill_bias(a, b);
  const float inverse_area = 1.0 / float(area);
  bool nearest = false;
  for (int y = box.y; y <= box.w; ++y) {
    int wa = row_a, wb = row_b, wc = row_c;
    for (int x = box.x; x <= box.z; ++x) {
      if (wa >= bias_a && wb >= bias_b && wc >= bias_c)
        nearest = update_pixel(ivec2(x, y), interpolate_depth(z, float(wb), float(wc), inverse_area), triangle) || nearest;
      wa += step_a.x;
      wb += step_b.x;
      wc += step_c.x;
    }
    row_a += step_a.y;
    row_b += step_b.y;
    row_c += step_c.y;
  }
#ifndef GLINT_RASTER_ONE_ROUND  // no round 1 to tell
  if (raster_round == 0u && nearest) touched[triangle] = run_stamp;
#endif
}
