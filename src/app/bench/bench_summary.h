#pragma once
// summary.json of a `glint bench` run: the environment, the settings, the backends (with why each
// unavailable one was skipped) and one entry per cell of the matrix, done, skipped or failed, with
// the statistics of its CSV. Everything in it is derived from the cells' files and the settings,
// never from the clock, so a resumed run that renders nothing writes the same summary again.
#include "app/bench/paper_matrix.h"
#include "core/enum_names.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::bench {

// What became of a cell in this run (or before it).
struct CellOutcome {
  enum class State { done, skipped, failed } state = State::done;
  std::string reason;     // skipped or failed: why
  bool resumed = false;   // done by an earlier run (its CSV was kept); not part of summary.json
};

inline constexpr EnumNames<CellOutcome::State, 3> kCellStateNames{
    "cell state",
    {{CellOutcome::State::done, "done"}, {CellOutcome::State::skipped, "skipped"}, {CellOutcome::State::failed, "failed"}}};

inline std::string_view state_name(CellOutcome::State state) { return kCellStateNames.name_of(state); }

// The summary entry of `cell`: what it measures and its outcome; for a done frame-times cell the
// statistics of its frame times (frame_ms: the steady-state time between consecutive frames'
// completions, deform and update included, as the paper's frame rate; and frame_latency_ms, each
// frame's start to its end), the means of its other columns and the interval means; for
// a done quality cell its rows; and the side file's scene statistics (scene_stats) and tracer
// statistics (ray_tracer). `interval`: measured frames
// per interval mean. glint::Error when a done cell's files cannot be read.
nlohmann::json cell_summary(const Cell& cell, const CellOutcome& outcome, const std::filesystem::path& out,
                            std::size_t interval);

// Writes DIR/summary.json atomically.
void write_summary(const std::filesystem::path& out, const nlohmann::json& summary);

}  // namespace glint::bench
