// Passes that run only on some 8x8 tiles of the frame (`--reflections auto`: SSR, ray list) are
// dispatched indirectly with one work group per entry of a tile list (render/tile_dispatch.h):
// entry = tile index (row-major over tile_columns tiles per row) | class << 28. With use_tile_list
// 0 the pass is a plain dispatch over the whole image and these are the global invocation ids.
layout(std430, binding = 20) readonly buffer TileList { uint tile_list[]; };
uniform int use_tile_list;
uniform int tile_columns;

uint tile_list_entry() { return tile_list[gl_WorkGroupID.x]; }
uint tile_list_class() { return use_tile_list == 0 ? 0u : tile_list_entry() >> 28; }

ivec2 tile_list_pixel() {
  if (use_tile_list == 0) return ivec2(gl_GlobalInvocationID.xy);
  const int tile = int(tile_list_entry() & 0x0fffffffu);
  return ivec2(tile % tile_columns, tile / tile_columns) * 8 + ivec2(gl_LocalInvocationID.xy);
}
