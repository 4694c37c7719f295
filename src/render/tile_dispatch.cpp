#include "render/tile_dispatch.h"

#include "render/compute_dispatch.h"

namespace glint::render {

int tile_columns(int width) { return (width + kReflectionTileSize - 1) / kReflectionTileSize; }
int tile_rows(int height) { return (height + kReflectionTileSize - 1) / kReflectionTileSize; }

void dispatch_image_or_tiles(ShaderProgram& program, const std::optional<TileListDispatch>& tiles, int width,
                             int height) {
  static_assert(kReflectionTileSize == static_cast<int>(kImageTileSize));
  program.set_uniform("use_tile_list", tiles ? 1 : 0);
  program.use();
  if (!tiles) {
    dispatch_over_image(width, height);
    return;
  }
  program.set_uniform("tile_columns", tiles->tile_columns);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, kTileListBinding, tiles->list_buffer, tiles->list_offset,
                    tiles->list_bytes);
  // The classification wrote the sizes with shader atomics.
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, tiles->dispatch_buffer);
  glDispatchComputeIndirect(tiles->indirect_offset);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

}  // namespace glint::render
