// The compute rasteriser's triangle arithmetic shared by its dispatches (ComputeVisibilityPass):
// fetching and transforming a triangle, snapping, the fill rule, depth, and what a covered pixel
// does in each round. 32-bit only; compute_raster_large.glsl adds the 64-bit edge functions.
// Needs frame_constants.glsl, scene_geometry.glsl, scene_instances.glsl and
// compute_visibility_buffers.glsl.
//
// Conventions, those of the id draw (GL window space, depth range [0, 1], GL_LESS against a clear
// of 1): corners are snapped to 1/256 pixel (the sub-pixel grid of NVIDIA's and llvmpipe's
// rasterisers); pixel (x, y) is covered when its centre (x + 1/2, y + 1/2) is inside, by exact
// integer edge functions; a centre exactly on an edge belongs to the triangle for which that edge
// is a left or a bottom edge (GL window space, y up: Mesa llvmpipe's rule, so both agree on every
// pixel there; tests/render/compute_visibility_test.cpp), so two triangles sharing an edge cover
// each centre on it once. Depth is the window z interpolated linearly in screen space at the
// centre; 0 <= depth < 1 is drawn.

uniform uint raster_round;  // 0: nearest depth per pixel; 1: first triangle in draw order at that depth
uniform uint instance_count;

const int kSubpixelOne = 256;  // 1 pixel in snapped units
const int kHalfPixel = 128;
const int kSubpixelShift = 8;
// Corners within |x|, |y| <= kGuardBand * w are rasterised as they are; a triangle reaching further
// (or in front of the near plane) is clipped to that band first. Snapped coordinates then stay
// within (kGuardBand + 1) / 2 x the viewport's size x 256, so 64-bit edge functions are exact.
const float kGuardBand = 2.0;

// Triangle `triangle` (draw order) in clip space, transformed as visibility.vert.glsl does.
void fetch_triangle(uint triangle, out vec4 corner[3]) {
  const uint instance = instance_of_triangle(triangle, instance_count);
  const uint in_mesh = triangle - instance_first_triangle[instance];
  const GpuMeshRange range = mesh_ranges[instances[instance].mesh];
  const mat4 model = instances[instance].model;
  for (uint k = 0u; k < 3u; ++k) {
    const uint index = indices[range.first_index + 3u * in_mesh + k];
    const vec4 world = model * vec4(vertices[range.base_vertex + index].position_u.xyz, 1.0);
    corner[k] = clip_from_world(world.xyz);
  }
}

// Bits of the frustum planes a clip-space point is outside of.
uint outcode(vec4 p) {
  return uint(p.x > p.w) | (uint(p.x < -p.w) << 1) | (uint(p.y > p.w) << 2) | (uint(p.y < -p.w) << 3) |
         (uint(p.z > p.w) << 4) | (uint(p.z < -p.w) << 5);
}

// In front of the near plane (z < -w, which every point at or behind the eye is) or outside the
// guard band: a triangle with such a corner is clipped before it is snapped (a corner near w = 0
// would project far off, and the depths interpolated from it would lose their precision).
bool needs_clipping(vec4 p) { return p.z < -p.w || abs(p.x) > kGuardBand * p.w || abs(p.y) > kGuardBand * p.w; }

ivec2 snap_to_window(vec4 clip) {
  const vec2 half_size = 0.5 * vec2(viewport.xy);
  precise vec2 window = clip.xy * (1.0 / clip.w) * half_size + half_size;
  return ivec2(floor(window * float(kSubpixelOne) + 0.5));
}

float window_depth(vec4 clip) {
  precise float z = clip.z * (1.0 / clip.w) * 0.5 + 0.5;
  return z;
}

// The pixel centres within the snapped corners' bounds, clamped to the viewport (x0, y0, x1, y1;
// empty when x0 > x1 or y0 > y1). >> rounds towards minus infinity on signed integers.
ivec4 pixel_box(ivec2 lo, ivec2 hi) {
  const ivec4 box = ivec4((lo - kHalfPixel + (kSubpixelOne - 1)) >> kSubpixelShift, (hi - kHalfPixel) >> kSubpixelShift);
  return ivec4(max(box.xy, ivec2(0)), min(box.zw, viewport.xy - 1));
}

bool box_empty(ivec4 box) { return any(greaterThan(box.xy, box.zw)); }

// Minimum edge value a covered centre needs: 0 on a left or bottom edge, 1 otherwise (counter-
// clockwise, y up: a left edge runs downwards, a bottom edge is horizontal and runs to +x).
int fill_bias(ivec2 u, ivec2 v) {
  const ivec2 d = v - u;
  return (d.y < 0 || (d.y == 0 && d.x > 0)) ? 0 : 1;
}

// Window depth from the edge values of corners b and c (barycentric weight x area).
float interpolate_depth(vec3 z, float weight_b, float weight_c, float inverse_area) {
  precise float depth = z.x + (weight_b * inverse_area) * (z.y - z.x) + (weight_c * inverse_area) * (z.z - z.x);
  return depth;
}

// What a covered pixel does: round 0 keeps the nearest depth, round 1 the first triangle in draw
// order among those at exactly the kept depth (the same arithmetic gives the same bits both times).
// Round 0 returns false when the triangle cannot be kept there: the pixel already holds a nearer
// depth (a stale read is only larger, so false is always right). With GLINT_RASTER_ONE_ROUND one
// 64-bit atomicMin of {depth key, triangle} does both rounds' work at once.
bool update_pixel(ivec2 pixel, float depth, uint triangle) {
  if (!(depth >= 0.0 && depth < 1.0)) return false;  // clipped by the near or far plane, or not nearer than the clear
  const uint key = depth > 0.0 ? floatBitsToUint(depth) : 0u;  // -0 is 0
  const uint i = uint(pixel.y * viewport.x + pixel.x);
#ifdef GLINT_RASTER_ONE_ROUND
  // The key word alone (a 32-bit read cannot tear): the pair only decreases, so a key above the
  // one read can never be kept.
  if (key > depth_pair_words[2u * i + 1u]) return false;
  atomicMin(depth_pairs[i], packUint2x32(uvec2(triangle, key)));
  return true;
#else
  const uint kept = depth_keys[i];
  if (raster_round == 0u) {
    if (key < kept) atomicMin(depth_keys[i], key);
  } else if (kept == key) {
    atomicMin(winners[i], triangle);
  }
  return key <= kept;
#endif
}
