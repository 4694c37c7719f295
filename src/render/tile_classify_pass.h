#pragma once
// TileClassifyPass: the GPU half of `--reflections auto` (docs/hybrid.md "auto"). One compute
// dispatch of shaders/tile_classify.comp.glsl per frame, before SSR, one work group per 8x8 tile:
// reprojects what SSR did last frame onto this frame's pixels, counts per tile its reflective, known
// and SSR-failed pixels, classifies the tile with the host's thresholds (tile_classification.h) and
// writes the SSR and ray tile lists with their indirect dispatch sizes (tile_dispatch.h). It keeps
// two frames of per-pixel outcomes and per-tile evidence (ping-pong), and copies each frame's
// counts and evidence into readback slots for the host.
//   inputs:  G-buffer albedo_reflectivity, world_position; SSR's failure mask (still last frame's);
//            this and last frame's view-projection
//   outputs: tile lists, dispatch block, evidence; zeroes the reflection image outside SSR tiles
#include "core/math.h"
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"
#include "gl/shader_program.h"
#include "render/tile_classification.h"
#include "render/tile_dispatch.h"

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace glint::render {

struct TileClassifyInputs {
  GLuint albedo_reflectivity = 0;    // kAlbedoReflectivityFormat
  GLuint world_position = 0;         // kWorldPositionFormat
  GLuint previous_failure_mask = 0;  // kFailureMaskFormat: SSR's mask, as last frame left it
  GLuint reflection = 0;             // kReflectionFormat: zeroed where SSR does not run this frame
  mat4 view_projection{1.0f};        // this frame's
};

// A frame's tiles as the host reads them back.
struct TileFrameReadback {
  TileDispatchBlock block{};
  std::vector<TileEvidence> tiles;        // row-major
  std::vector<TileClass> classes;         // per tile
};

class TileClassifyPass {
public:
  TileClassifyPass(int width, int height);  // needs a current GL context

  // With `every_tile`, each tile that has a reflective pixel gets that class instead of the rule's.
  void run(const TileClassifyInputs& inputs, const TileThresholds& thresholds,
           std::optional<TileClass> every_tile = std::nullopt);
  // Forget the history (the next run() knows nothing of earlier frames): a cut in the walkthrough.
  void reset_history() { have_history_ = false; }

  TileListDispatch ssr_tiles() const;
  TileListDispatch ray_tiles() const;

  // Queues copies of the last run()'s block and evidence into readback slot `slot`; take() reads them
  // once the GPU is past them (nullopt if not yet and !wait).
  void request_readback(std::size_t slot);
  std::optional<TileFrameReadback> take(std::size_t slot, bool wait);
  bool readback_ready(std::size_t slot);
  // The last run()'s tiles; waits for the GPU (tests, debug views).
  TileFrameReadback read() const;

  int tile_columns() const { return columns_; }
  int tile_rows() const { return rows_; }
  std::size_t tile_count() const { return static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_); }

private:
  TileFrameReadback decode(const std::byte* block, const std::byte* evidence) const;

  ShaderProgram program_;
  int width_, height_, columns_, rows_;
  std::size_t ray_list_offset_;  // entries
  std::array<GlTexture, 2> outcome_;
  std::array<GlBuffer, 2> evidence_;
  GlBuffer lists_;
  GlBuffer dispatch_;
  int current_ = 0;
  bool have_history_ = false;
  mat4 previous_view_projection_{1.0f};
  ReadbackRing block_readback_;
  ReadbackRing evidence_readback_;
};

}  // namespace glint::render
