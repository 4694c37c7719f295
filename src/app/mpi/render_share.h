#pragma once
// `mpirun -np N glint render ...` (docs/scale-out.md): the frames run_render_command chose, shared
// over the ranks in contiguous pieces that rank 0 hands out as ranks ask (work_share.h). Rank 0
// prepares --out (refusing or replacing an earlier run as one process does) before any rank writes;
// each rank renders its pieces on its own GPU (rank_devices.h) through one FrameLoop, writes their
// PNGs (and debug views) into --out itself and sends their timings.csv and scopes.csv rows to rank 0,
// which writes timings.csv, scopes.csv, the video (from the PNGs, in frame order) and run.json as one
// process would; run.json adds "distribution" (ranks, pieces, who rendered what). A rank whose piece
// fails is reported and takes no more; its piece goes to another rank.
#include "app/render_command.h"
#include "render/frame_pipeline.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <vector>

namespace glint::mpi {

// Frames per piece: GLINT_MPI_PIECE_FRAMES when set, else about eight pieces per rank (a piece
// boundary only empties the pipeline once; the loop and its structures carry on).
std::size_t render_piece_frames(std::size_t frames, int ranks);

// Every rank calls it in place of the one-process loop; returns the command's exit status. `recorded`:
// the options run.json names; `about`: what this rank says of itself (rank_devices.h).
int run_render_shared(const RenderOptions& options, const RenderOptions& recorded,
                      const render::FramePipelineSettings& settings, Scene& scene, const std::vector<int>& frames,
                      const nlohmann::json& about);

}  // namespace glint::mpi
