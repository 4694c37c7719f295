#pragma once
// ComputeVisibilityPass: the visibility G-buffer's ids rasterised by compute shaders instead of the
// id draw (PrimaryVisibility::compute, docs/render.md "Compute-rasterised primary visibility"). It
// writes exactly what VisibilityIdPass writes, so VisibilityGBufferPass and every later pass read the
// same inputs:
//   inputs:  GpuScene (vertices read every frame: deforming meshes change them), FrameConstants UBO
//   outputs: RasterTargets visibility_id ({instance + 1, triangle}, {0, 0} background); depth
//            (window-space z in [0, 1], 1 where nothing was drawn, as the id draw leaves it) after
//            write_depth()
// GL compute work spreads over every SM of a GPU, where vertex and fragment work may not (the H100
// runs them on a few). A pixel keeps the nearest depth (round 0: 32-bit atomicMin on the depth's
// float bits), then, among the triangles with exactly that depth there, the first in draw order
// (round 1: atomicMin on the triangle's number over all instances), as the id draw's GL_LESS keeps
// the first of equal depths. Where the driver has 64-bit atomics on storage buffers
// (GL_NV_shader_atomic_int64: NVIDIA's), one atomicMin on {depth bits, triangle} in a 64-bit word
// does both at once and round 1 is skipped (0.14 ms of 0.63 at 1280x720 on an H100); Mesa's
// llvmpipe (the test machines) has none and takes the two rounds. Dispatches of run()
// (shaders/compute_visibility_*):
//   reset      every pixel to "nothing drawn", the counters to their start
//   triangles  one invocation per triangle of every instance, in draw order: transform, cull outside
//              a frustum plane or covering no pixel centre, snap the corners to 1/256 pixel; a small
//              triangle (at most 64 candidate centres) is rasterised there with 32-bit edge
//              functions; the others (larger, or in front of the near plane or beyond the guard band)
//              go to the deferred list (round 0)
//   large      one invocation per deferred triangle: clip to the near plane and the guard band, fan
//              the polygon, append the pieces to the large-triangle list (round 0)
//              and their 8x8-pixel tiles to the chunk list, records of up to 8 tiles (more for a
//              huge piece: at most 256 records a piece)
//   chunk_dispatch  one invocation: the tile dispatch's size from the chunk count
//   tiles      one work group per chunk record, one invocation per pixel of a tile, walking the
//              record's tiles; 64-bit edge functions
//   triangles (only those round 0 found nearest somewhere), large and tiles again for round 1
//   over the same lists (two-round machines only); then
//   ids        one invocation per pixel: the kept triangle's id into the id image.
// The depth target is written only on demand (write_depth: a full-screen draw, since compute
// shaders cannot write a depth texture): no frame pass reads it, and the draw runs on the graphics
// SMs (0.20 ms at 1280x720, 0.79 ms at 2560x1440 on an H200, where the ids dispatch replaces it).
// Coverage is exact (integer edge functions at pixel centres) with llvmpipe's fill rule, so
// triangles sharing an edge leave no crack and cover no centre twice. When the large-triangle list
// or the chunk list is full, a deferred triangle is rasterised by its own invocation in both rounds:
// slow but correct.
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/raster_targets.h"

#include <cstdint>

namespace glint::render {

struct ComputeVisibilityOptions {
  // Entries of the large-triangle list; 0: one per 8 pixels, at least 16384 (the .cpp says why).
  // Tests make it small to exercise the full-list path.
  std::uint32_t large_triangle_capacity = 0;
  // Records of the tile dispatch's chunk list; 0: twice the large-triangle capacity. Tests make it
  // small to exercise its full-list path.
  std::uint32_t tile_chunk_capacity = 0;
  // false: the two 32-bit rounds even where 64-bit atomics exist (tests compare the two).
  bool use_64_bit_atomics = true;
};

// What the last run's large-triangle list held (read back: tests and debugging only).
struct ComputeVisibilityStats {
  std::uint32_t deferred = 0;       // triangles left to the large-triangle dispatch
  std::uint32_t large_entries = 0;  // entries written (clipped triangles give up to 6)
  std::uint32_t chunks = 0;         // records of the chunk list written (each up to 8 tiles or more)
  std::uint32_t overflowed = 0;     // triangles rasterised by their own invocation (list full)
};

class ComputeVisibilityPass {
public:
  // The targets must hold visibility_id (RasterTargets(w, h, true)) and outlive the pass, as must
  // `scene` (its instance-to-mesh assignment is fixed here; vertices and transforms are read every
  // run). glint::Error otherwise. Needs a current GL context.
  ComputeVisibilityPass(const RasterTargets& targets, const GpuScene& scene, const ComputeVisibilityOptions& options = {});

  // Writes visibility_id for this frame (FrameConstants bound at kFrameConstantsBinding). Ends with
  // a barrier that makes the id image visible to image loads and texture fetches.
  void run();
  // Writes the last run's depths into the depth target (and the same ids again), for a reader of the
  // depth (RasterPipeline::read_rgbaf, debug views, tests). FrameConstants bound as for run().
  void write_depth() const;

  std::uint32_t large_triangle_capacity() const { return capacity_; }
  // Whether run() keeps {depth, triangle} in one 64-bit atomic per pixel (one raster round).
  bool one_round() const { return one_round_; }
  std::uint32_t triangle_count() const { return triangle_count_; }
  // Waits for the GPU.
  ComputeVisibilityStats read_stats() const;

private:
  // Two rounds only: a new run stamp, and touched_ bound, for round 0 to mark the triangles round 1
  // redoes. One round has no round 1: its shaders (GLINT_RASTER_ONE_ROUND) declare no stamps.
  void stamp_run();

  const RasterTargets* targets_;
  const GpuScene* scene_;
  bool one_round_;  // before the programs: it picks their variant
  std::uint32_t triangle_count_ = 0;
  std::uint32_t instance_count_ = 0;
  std::uint32_t capacity_ = 0;        // large-triangle entries
  std::uint32_t chunk_capacity_ = 0;  // chunk records
  GLuint reset_groups_ = 0;  // of the reset dispatch, set once: the targets keep the size the buffers have
  GlBuffer depth_keys_, winners_;          // one uint per pixel each; one_round_: one uint64 in depth_keys_, no winners_
  GlBuffer large_triangles_;                // capacity_ entries
  GlBuffer tile_chunks_;                    // chunk_capacity_ records
  GlBuffer counters_;                       // ComputeVisibilityCounters (the .cpp), indirect dispatch inside
  GlBuffer instance_first_triangle_;        // instance_count_ + 1 uints
  GlBuffer deferred_;                       // triangle_count_ + 1 uints: room for every triangle
  GlBuffer touched_;                        // triangle_count_ + 1 uints: run stamps (two rounds only)
  std::uint32_t run_stamp_ = 0;             // of the last two-round run; touched_ starts at 0
  ShaderProgram reset_program_, triangle_program_, large_program_, chunk_dispatch_program_, tile_program_, ids_program_, resolve_program_;
  GlFramebuffer framebuffer_;
  GlVertexArray empty_vertex_array_;
};

}  // namespace glint::render
