// The compute rasteriser's large triangles (ComputeVisibilityPass): set-up and coverage with 64-bit
// edge functions, exact anywhere in the guard band, and the large-triangle list's entries. Needs
// compute_raster.glsl and GL_ARB_gpu_shader_int64 (compute_raster_extensions.glsl).

struct ScreenTriangle {
  ivec2 a, b, c;  // snapped window positions, counter-clockwise (positive area)
  vec3 z;         // window depths at a, b, c
  ivec4 box;      // covered pixel range (pixel_box)
};

// Twice the signed area of (u, v, p): positive when p lies left of u -> v (y up).
int64_t edge64(ivec2 u, ivec2 v, ivec2 p) {
  return int64_t(v.x - u.x) * int64_t(p.y - u.y) - int64_t(v.y - u.y) * int64_t(p.x - u.x);
}

// Sets up the triangle of three clip-space corners inside the guard band. False when it covers no
// pixel centre of the viewport or has no area once snapped.
bool setup_triangle(vec4 p0, vec4 p1, vec4 p2, out ScreenTriangle t) {
  t.a = snap_to_window(p0);
  t.b = snap_to_window(p1);
  t.c = snap_to_window(p2);
  t.z = vec3(window_depth(p0), window_depth(p1), window_depth(p2));
  t.box = pixel_box(min(t.a, min(t.b, t.c)), max(t.a, max(t.b, t.c)));
  if (box_empty(t.box)) return false;
  const int64_t area = edge64(t.a, t.b, t.c);
  if (area == 0l) return false;
  if (area < 0l) {  // both faces are drawn: turn it counter-clockwise
    const ivec2 b = t.b;
    t.b = t.c;
    t.c = b;
    t.z = t.z.xzy;
  }
  return true;
}

// One pixel of the triangle.
void raster_pixel(ScreenTriangle t, ivec2 pixel, uint triangle) {
  const ivec2 centre = pixel * kSubpixelOne + kHalfPixel;
  const int64_t wa = edge64(t.b, t.c, centre), wb = edge64(t.c, t.a, centre), wc = edge64(t.a, t.b, centre);
  if (wa < int64_t(fill_bias(t.b, t.c)) || wb < int64_t(fill_bias(t.c, t.a)) || wc < int64_t(fill_bias(t.a, t.b))) return;
  update_pixel(pixel, interpolate_depth(t.z, float(wb), float(wc), 1.0 / float(wa + wb + wc)), triangle);
}

// Every pixel of the triangle's box by one invocation (when the large-triangle list is full).
void raster_box(ScreenTriangle t, uint triangle) {
  for (int y = t.box.y; y <= t.box.w; ++y)
    for (int x = t.box.x; x <= t.box.z; ++x) raster_pixel(t, ivec2(x, y), triangle);
}

// The tile dispatch's tiles: 8x8 pixels (its work group), numbered row by row over the entry's pixel
// box from its lower left corner.
const int kTileSize = 8;
uint tiles_across(ivec4 box) { return uint((box.z - box.x + kTileSize) / kTileSize); }
uint tile_total(ivec4 box) { return tiles_across(box) * uint((box.w - box.y + kTileSize) / kTileSize); }

// How many consecutive tiles of an entry of `tiles` tiles one work group walks: 8 (most entries,
// a few tiles, take one group; a group's loads of the entry are shared by 8 tiles), more for a huge
// entry, so that one piece never has more than 256 records: the large dispatch writes a piece's
// records one by one in one invocation.
const uint kMinChunkTiles = 8u;
const uint kMaxChunksPerPiece = 256u;
uint chunk_tiles(uint tiles) { return max(kMinChunkTiles, (tiles + kMaxChunksPerPiece - 1u) / kMaxChunksPerPiece); }
uint chunk_count_of(uint tiles) {
  const uint per_chunk = chunk_tiles(tiles);
  return (tiles + per_chunk - 1u) / per_chunk;
}

LargeTriangle pack_large_triangle(ScreenTriangle t, uint triangle) {
  return LargeTriangle(ivec4(t.a, t.b), ivec4(t.c, int(triangle), 0), vec4(t.z, 0.0), t.box);
}

ScreenTriangle unpack_large_triangle(LargeTriangle e, out uint triangle) {
  triangle = uint(e.corner_c_number.z);
  return ScreenTriangle(e.corners_ab.xy, e.corners_ab.zw, e.corner_c_number.xy, e.depths.xyz, e.box);
}
