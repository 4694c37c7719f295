#pragma once
// Passes dispatched over a list of 8x8 tiles instead of the whole image (`--reflections auto`):
// TileClassifyPass writes the lists and the indirect dispatch sizes on the GPU; SsrPass and
// RayListPass run one work group per listed tile (glDispatchComputeIndirect), so tiles that skip a
// stage cost it nothing. A list entry is tile | class << 28 (tile: row-major index over
// ceil(width / 8) tiles per row); shaders read it through shaders/include/tile_list.glsl.
#include "gl/shader_program.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <optional>

namespace glint::render {

inline constexpr int kReflectionTileSize = 8;  // = the image passes' work group (compute_dispatch.h)

// Storage bindings of the tile classification (render_targets.h lists the others).
inline constexpr GLuint kTileListBinding = 20;              // uint[]: the list a pass runs over
inline constexpr GLuint kTileEvidenceBinding = 21;          // uvec4[tiles]: reflective, known, failed, class
inline constexpr GLuint kPreviousTileEvidenceBinding = 22;  // the same, last frame
inline constexpr GLuint kTileDispatchBinding = 23;          // TileDispatchBlock

// The GPU's block at kTileDispatchBinding (std430, tile_classify.comp.glsl, ray_budget_clamp.comp.glsl).
struct TileDispatchBlock {
  std::uint32_t ssr_groups[3];    // indirect dispatch of SSR: listed tiles, 1, 1
  std::uint32_t ray_groups[3];    // indirect dispatch of the ray list
  std::uint32_t class_tiles[4];   // tiles per render::TileClass
  std::uint32_t class_pixels[4];  // reflective pixels per class
  std::uint32_t rays_wanted;      // rays the ray list asked for before the budget cut them
  std::uint32_t padding[3];
};
static_assert(sizeof(TileDispatchBlock) == 18 * sizeof(std::uint32_t));
inline constexpr GLintptr kSsrIndirectOffset = 0;
inline constexpr GLintptr kRayIndirectOffset = 3 * sizeof(std::uint32_t);

// Where a pass finds its tile list and its dispatch size.
struct TileListDispatch {
  GLuint list_buffer = 0;
  GLintptr list_offset = 0;  // bytes; a multiple of the storage-buffer offset alignment
  GLsizeiptr list_bytes = 0;
  GLuint dispatch_buffer = 0;  // holds the TileDispatchBlock
  GLintptr indirect_offset = 0;
  int tile_columns = 0;
};

// Tiles of a width x height image (rounded up).
int tile_columns(int width);
int tile_rows(int height);

// Dispatches the bound `program` (which includes tile_list.glsl) over the listed tiles, or, without a
// list, over the whole width x height image in 8x8 work groups.
void dispatch_image_or_tiles(ShaderProgram& program, const std::optional<TileListDispatch>& tiles, int width,
                             int height);

}  // namespace glint::render
