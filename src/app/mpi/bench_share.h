#pragma once
// `mpirun -np N glint bench ...` (docs/scale-out.md): the cells bench_command planned, shared over the
// ranks. Every rank plans the same cells from the same flags; they become pieces (a whole cell, or a
// range of a long frame-times cell's frames) that rank 0 hands out as ranks ask (work_share.h), the
// longest first. Each rank renders its pieces on its own GPU (rank_devices.h) and writes their files
// into the shared --out folder itself: a whole cell's files as a one-process run writes them, a
// range's under cells/parts/. Rank 0 then joins each split cell's ranges, in frame order, into the
// cell's CSV and side file and writes summary.json, report.md and the charts as a one-process run.
//
// A frame-times cell split into ranges measures each range after its own --warmup frames and its own
// structure build, so its statistics pool the ranges' steady states; summary.json ("distribution")
// and report.md say how many ranks and pieces the run had and which cells were split.
#include "app/bench/bench_summary.h"
#include "app/bench/cell_run.h"
#include "app/bench/paper_matrix.h"
#include "core/progress_bar.h"
#include "gl/egl_context.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint::mpi {

// One cell of the run as bench_command planned it (pointers into its plan).
struct BenchCellPlan {
  const bench::Cell* cell = nullptr;
  const std::vector<int>* frames = nullptr;
  bool to_run = false;
};

// A piece: a whole cell, or frames [first, first + count) of a frame-times cell's list.
struct BenchPiece {
  std::size_t cell = 0;  // index into the plans
  bool whole = true;
  std::size_t first = 0;
  std::size_t count = 0;
  std::size_t ticks = 0;  // progress ticks (bench::cell_ticks): what the longest-first order sorts by
};

// Measured frames per range of a split frame-times cell: GLINT_MPI_PIECE_FRAMES when set (a positive
// number), else enough for about four pieces per rank over `total_frames` frame-times frames but
// never under 100 (each range pays its own warm-up and build); 0 (no split) with one rank.
std::size_t piece_frames_for(std::size_t total_frames, int ranks);

// The pieces of the cells to run, longest first: a frame-times cell of more than `piece_frames`
// frames (0: never) in ceil(frames / piece_frames) ranges of nearly equal length, every other cell
// whole.
std::vector<BenchPiece> bench_pieces(const std::vector<BenchCellPlan>& plans, std::size_t piece_frames,
                                     const bench::CellRunSettings& settings);

// The id under which a range of `cell` writes its files: "parts/<id>.frames-<first>-<last>", so
// cells/parts/<id>.frames-00000-01224.csv (and .json).
std::string part_id(const bench::Cell& cell, int first_frame, int last_frame);

struct SharedBenchRun {
  // Per plan: what became of a cell to run; nullopt for one the time limit left (not started, or a
  // split cell with ranges not started: its finished ranges stay in cells/parts/).
  std::vector<std::optional<bench::CellOutcome>> outcomes;
  nlohmann::json distribution;  // summary.json's "distribution"
  bool time_limit_reached = false;
};

// Runs the plans' cells to run over the ranks (every rank calls it, after rank 0 prepared --out).
// Rank 0 gets every cell's outcome, its split cells joined; the other ranks get nullopt. `about`:
// what this rank says of itself (rank_devices.h), with its GL renderer. No piece starts after
// `hand_out_until` (--time-limit).
std::optional<SharedBenchRun> run_bench_shared(const std::vector<BenchCellPlan>& plans,
                                               const std::map<std::string, Scene>& scenes,
                                               const bench::CellRunSettings& settings, const HeadlessGlContext& context,
                                               const std::filesystem::path& out, ProgressBar& progress,
                                               const nlohmann::json& about,
                                               std::optional<std::chrono::steady_clock::time_point> hand_out_until);

// report.md's section on the ranks (empty when summary.json has no "distribution": one process).
std::string distribution_markdown(const nlohmann::json& summary);

// Where a rank's progress bar prints: stderr on rank 0 (and in a one-process run), nowhere on the
// others (mpirun would interleave their lines).
ProgressOutput rank_progress_output();

}  // namespace glint::mpi
