#include "app/mpi/bench_share.h"

#include "app/bench/resume.h"
#include "app/mpi/mpi_world.h"
#include "app/mpi/work_share.h"
#include "core/atomic_file.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/log.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>

namespace glint::mpi {
namespace {

namespace fs = std::filesystem;
using bench::Cell;
using bench::CellKind;
using bench::CellOutcome;

constexpr std::size_t kMinAutoPieceFrames = 100;
constexpr std::size_t kPiecesPerRank = 4;

std::vector<int> frames_of(const BenchCellPlan& plan, const BenchPiece& piece) {
  return {plan.frames->begin() + static_cast<std::ptrdiff_t>(piece.first),
          plan.frames->begin() + static_cast<std::ptrdiff_t>(piece.first + piece.count)};
}

// The cell a piece renders: the cell itself, or a copy writing under cells/parts/.
Cell piece_cell(const BenchCellPlan& plan, const BenchPiece& piece) {
  Cell cell = *plan.cell;
  if (!piece.whole)
    cell.id = part_id(*plan.cell, (*plan.frames)[piece.first], (*plan.frames)[piece.first + piece.count - 1]);
  return cell;
}

std::string piece_text(const BenchCellPlan& plan, const BenchPiece& piece) {
  if (piece.whole) return plan.cell->id;
  return fmt::format("{} frames {}-{}", plan.cell->id, (*plan.frames)[piece.first],
                     (*plan.frames)[piece.first + piece.count - 1]);
}

// Whether an earlier run left this range finished (its CSV whole), so it is kept.
bool part_finished(const fs::path& out, const BenchCellPlan& plan, const BenchPiece& piece) {
  const std::optional<bench::CsvTable> table = bench::read_csv_table(bench::cell_csv_path(out, piece_cell(plan, piece)));
  if (!table) return false;
  std::vector<bench::RowKey> rows;
  for (const int frame : frames_of(plan, piece)) rows.push_back({std::to_string(frame)});
  return !bench::finished_cell_problem(*table, bench::cell_csv_header(CellKind::frame_times), rows);
}

nlohmann::json read_json_file(const fs::path& path) {
  std::ifstream file(path);
  if (!file) return nullptr;
  std::stringstream text;
  text << file.rdbuf();
  const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
  return json.is_discarded() ? nlohmann::json(nullptr) : json;
}

// "rank 1: <error>; rank 0: <error>": every attempt's error.
std::string attempts_text(const PieceScheduler::Piece& piece) {
  std::string text;
  for (const PieceScheduler::Attempt& attempt : piece.attempts) {
    if (attempt.error.empty()) continue;
    if (!text.empty()) text += "; ";
    text += attempt.rank < 0 ? attempt.error : fmt::format("rank {}: {}", attempt.rank, attempt.error);
  }
  return text;
}

// Joins a split cell's ranges (all finished, in frame order) into cells/<id>.csv and cells/<id>.json,
// then removes every range file of the cell.
void join_parts(const fs::path& out, const BenchCellPlan& plan, const std::vector<const BenchPiece*>& parts,
                const std::vector<nlohmann::json>& ran_by) {
  const Cell& cell = *plan.cell;
  const std::vector<std::string> header = bench::cell_csv_header(CellKind::frame_times);
  CsvWriter csv(bench::cell_csv_path(out, cell), header);
  nlohmann::json side = nullptr;
  nlohmann::json pieces = nlohmann::json::array();
  double wall_seconds = 0.0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Cell part = piece_cell(plan, *parts[i]);
    const std::optional<bench::CsvTable> table = bench::read_csv_table(bench::cell_csv_path(out, part));
    if (!table) fail("{}: a finished range of cell {} is missing", bench::cell_csv_path(out, part).string(), cell.id);
    for (const std::vector<std::string>& row : table->rows)
      csv.add_row(std::vector<CsvField>(row.begin(), row.end()));
    const nlohmann::json part_side = read_json_file(bench::cell_json_path(out, part));
    if (side.is_null() && part_side.is_object()) side = part_side;  // the first range: built as one process builds
    nlohmann::json entry = {{"frames", {(*plan.frames)[parts[i]->first], (*plan.frames)[parts[i]->first + parts[i]->count - 1]}},
                            {"measured_frames", parts[i]->count}};
    for (const auto& [key, value] : ran_by[i].items()) entry[key] = value;
    if (part_side.is_object()) {
      wall_seconds += part_side.value("wall_seconds", 0.0);
      for (const char* key : {"wall_seconds", "ray_tracer"})
        if (part_side.contains(key)) entry[key] = part_side[key];
    }
    pieces.push_back(entry);
  }
  if (!side.is_object()) side = nlohmann::json::object();
  side["id"] = cell.id;
  side["wall_seconds"] = wall_seconds;
  // Every range built its own structures and updated them over its frames.
  if (side.contains("ray_tracer") && side["ray_tracer"].is_object())
    for (const char* key : {"rebuilds", "refits"}) {
      long long total = 0;
      for (const nlohmann::json& piece : pieces)
        if (piece.contains("ray_tracer") && piece["ray_tracer"].is_object()) total += piece["ray_tracer"].value(key, 0LL);
      side["ray_tracer"][key] = total;
    }
  side["pieces"] = pieces;
  write_file_atomically(bench::cell_json_path(out, cell), side.dump(2) + "\n");
  csv.commit();
  // The ranges are in the cell now; ranges of another split (a run with other ranks) go too.
  const std::string prefix = cell.id + ".frames-";
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(out / "cells" / "parts", error))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) fs::remove(entry.path(), error);
}

}  // namespace

std::size_t piece_frames_for(std::size_t total_frames, int ranks) {
  if (const char* value = std::getenv("GLINT_MPI_PIECE_FRAMES"); value != nullptr && *value != '\0') {
    const std::string_view text(value);
    std::size_t frames = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), frames);
    if (error != std::errc() || end != text.data() + text.size() || frames == 0)
      fail("GLINT_MPI_PIECE_FRAMES={}: expected a positive number of frames", text);
    return frames;
  }
  if (ranks <= 1) return 0;
  const std::size_t pieces = kPiecesPerRank * static_cast<std::size_t>(ranks);
  return std::max(kMinAutoPieceFrames, (total_frames + pieces - 1) / pieces);
}

std::vector<BenchPiece> bench_pieces(const std::vector<BenchCellPlan>& plans, std::size_t piece_frames,
                                     const bench::CellRunSettings& settings) {
  std::vector<BenchPiece> pieces;
  for (std::size_t c = 0; c < plans.size(); ++c) {
    const BenchCellPlan& plan = plans[c];
    if (!plan.to_run) continue;
    const std::size_t frames = plan.frames->size();
    if (plan.cell->kind == CellKind::quality || piece_frames == 0 || frames <= piece_frames) {
      pieces.push_back({c, true, 0, frames, bench::cell_ticks(*plan.cell, frames, settings)});
      continue;
    }
    const std::size_t count = (frames + piece_frames - 1) / piece_frames;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t first = k * frames / count, end = (k + 1) * frames / count;
      pieces.push_back({c, false, first, end - first, bench::cell_ticks(*plan.cell, end - first, settings)});
    }
  }
  std::stable_sort(pieces.begin(), pieces.end(), [](const BenchPiece& a, const BenchPiece& b) { return a.ticks > b.ticks; });
  return pieces;
}

std::string part_id(const Cell& cell, int first_frame, int last_frame) {
  return fmt::format("parts/{}.frames-{:05d}-{:05d}", cell.id, first_frame, last_frame);
}

std::optional<SharedBenchRun> run_bench_shared(const std::vector<BenchCellPlan>& plans,
                                               const std::map<std::string, Scene>& scenes,
                                               const bench::CellRunSettings& settings, const HeadlessGlContext& context,
                                               const fs::path& out, ProgressBar& progress, const nlohmann::json& about,
                                               std::optional<std::chrono::steady_clock::time_point> hand_out_until) {
  // Every rank planned from the same files; none is written before all have (rank 0 would otherwise
  // finish a cell that a slower rank then plans as kept, and their lists of pieces would differ).
  barrier();
  std::size_t total_frames = 0;
  for (const BenchCellPlan& plan : plans)
    if (plan.to_run && plan.cell->kind == CellKind::frame_times) total_frames += plan.frames->size();
  const std::size_t piece_frames = piece_frames_for(total_frames, world().size);
  const std::vector<BenchPiece> all_pieces = bench_pieces(plans, piece_frames, settings);
  // Ranges an earlier run finished are kept (every rank sees the same files: the same list).
  std::vector<BenchPiece> pieces;
  std::size_t kept_parts = 0;
  for (const BenchPiece& piece : all_pieces) {
    if (!piece.whole && part_finished(out, plans[piece.cell], piece)) {
      ++kept_parts;
      progress.tick(piece.ticks);
      continue;
    }
    pieces.push_back(piece);
  }
  std::filesystem::create_directories(out / "cells" / "parts");

  nlohmann::json rank_about = about;
  rank_about["gl_renderer"] = context.renderer();
  const auto run = [&](std::size_t index) -> nlohmann::json {
    const BenchPiece& piece = pieces[index];
    const BenchCellPlan& plan = plans[piece.cell];
    bench::run_cell(piece_cell(plan, piece), scenes.at(plan.cell->scene), frames_of(plan, piece), settings, context,
                    out, progress);
    return {{"rank", world().rank}, {"host", world().host}};
  };
  WorkShareOptions share_options;
  share_options.hand_out_until = hand_out_until;
  const std::optional<ShareResult> shared = share_pieces(pieces.size(), run, rank_about, share_options,
                                                         [&](std::size_t index) { progress.tick(pieces[index].ticks); });
  if (!shared) return std::nullopt;

  SharedBenchRun result;
  result.outcomes.resize(plans.size());
  result.time_limit_reached = shared->queued_pieces() > 0;
  std::set<std::size_t> left_cells;  // a piece of theirs was left queued at the time limit
  // Whole cells: done or failed as the piece went. Split cells: joined once every range is finished.
  std::map<std::size_t, std::vector<std::string>> split_failures;
  std::set<std::size_t> split_cells;
  nlohmann::json retried = nlohmann::json::array();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const BenchPiece& piece = pieces[i];
    const PieceScheduler::Piece& outcome = shared->pieces[i];
    if (outcome.attempts.size() > 1 || outcome.state == PieceScheduler::State::failed)
      retried.push_back({{"piece", piece_text(plans[piece.cell], piece)},
                         {"state", outcome.state == PieceScheduler::State::done ? "done" : "failed"},
                         {"errors", attempts_text(outcome)}});
    if (outcome.state == PieceScheduler::State::queued) {
      left_cells.insert(piece.cell);
      continue;
    }
    if (!piece.whole) {
      split_cells.insert(piece.cell);
      if (outcome.state != PieceScheduler::State::done)
        split_failures[piece.cell].push_back(fmt::format("frames {}-{}: {}", (*plans[piece.cell].frames)[piece.first],
                                                         (*plans[piece.cell].frames)[piece.first + piece.count - 1],
                                                         attempts_text(outcome)));
      continue;
    }
    result.outcomes[piece.cell] = outcome.state == PieceScheduler::State::done
                                      ? CellOutcome{CellOutcome::State::done, "", false}
                                      : CellOutcome{CellOutcome::State::failed, attempts_text(outcome), false};
  }
  for (const BenchPiece& piece : all_pieces)
    if (!piece.whole) split_cells.insert(piece.cell);
  std::size_t split_count = 0;
  for (const std::size_t c : split_cells) {
    ++split_count;
    if (left_cells.contains(c)) continue;  // its finished ranges wait in cells/parts/ for the rest
    if (split_failures.contains(c)) {
      std::string reason;
      for (const std::string& failure : split_failures[c]) reason += (reason.empty() ? "" : "; ") + failure;
      result.outcomes[c] = CellOutcome{CellOutcome::State::failed,
                                       reason + " (the finished ranges stay in cells/parts/; the same command runs the rest)",
                                       false};
      continue;
    }
    std::vector<const BenchPiece*> parts;
    std::vector<nlohmann::json> ran_by;
    for (const BenchPiece& piece : all_pieces)
      if (piece.cell == c) parts.push_back(&piece);
    std::sort(parts.begin(), parts.end(), [](const BenchPiece* a, const BenchPiece* b) { return a->first < b->first; });
    for (const BenchPiece* part : parts) {
      nlohmann::json by = {{"rank", nullptr}};  // kept from an earlier run
      for (std::size_t i = 0; i < pieces.size(); ++i)
        if (pieces[i].cell == c && pieces[i].first == part->first) by = shared->results[i];
      ran_by.push_back(by);
    }
    try {
      join_parts(out, plans[c], parts, ran_by);
      result.outcomes[c] = CellOutcome{CellOutcome::State::done, "", false};
    } catch (const Error& error) {
      result.outcomes[c] = CellOutcome{CellOutcome::State::failed, error.what(), false};
    }
  }

  std::error_code ignored;
  fs::remove(out / "cells" / "parts", ignored);  // when empty: every split cell was joined
  nlohmann::json ranks = nlohmann::json::array();
  std::set<std::string> hosts;
  for (const RankReport& report : shared->ranks) {
    nlohmann::json entry = report.about.is_object() ? report.about : nlohmann::json::object();
    entry["rank"] = report.rank;
    entry["pieces_done"] = report.pieces_done;
    if (report.failure) entry["failure"] = *report.failure;
    if (entry.contains("host")) hosts.insert(entry["host"].get<std::string>());
    ranks.push_back(entry);
  }
  result.distribution = {{"ranks", world().size},
                         {"hosts", hosts.size()},
                         {"pieces", pieces.size()},
                         {"kept_ranges", kept_parts},
                         {"piece_frames", piece_frames},
                         {"split_cells", split_count},
                         {"per_rank", ranks},
                         {"retried_or_failed_pieces", retried}};
  return result;
}

std::string distribution_markdown(const nlohmann::json& summary) {
  if (!summary.contains("distribution")) return "";
  const nlohmann::json& d = summary["distribution"];
  std::string text = "## Ranks\n\n";
  text += fmt::format(
      "Shared over {} MPI ranks on {} host(s) (docs/scale-out.md): {} piece(s) handed out as ranks asked for them",
      d["ranks"].get<int>(), d["hosts"].get<std::size_t>(), d["pieces"].get<std::size_t>());
  if (d["split_cells"].get<std::size_t>() > 0)
    text += fmt::format(
        "; {} frame-times cell(s) were split into ranges of at most {} measured frames, each range rendering its "
        "own {} warm-up frame(s) and building its own structures before its first measured frame, so their "
        "statistics pool the ranges' steady states (`pieces` in cells/<id>.json names them)",
        d["split_cells"].get<std::size_t>(), d["piece_frames"].get<std::size_t>(),
        summary["settings"]["warmup_frames"].get<int>());
  if (d["kept_ranges"].get<std::size_t>() > 0)
    text += fmt::format("; {} range(s) were kept from an earlier run", d["kept_ranges"].get<std::size_t>());
  text += ".\n\n| rank | host | GPU | GL renderer | pieces | failure |\n|---:|---|---|---|---:|---|\n";
  for (const nlohmann::json& rank : d["per_rank"]) {
    const auto text_of = [&](const char* key) {
      return rank.contains(key) && !rank[key].is_null() ? (rank[key].is_string() ? rank[key].get<std::string>() : rank[key].dump())
                                                        : std::string("-");
    };
    text += fmt::format("| {} | {} | EGL {}, CUDA {} | {} | {} | {} |\n", rank["rank"].get<int>(), text_of("host"),
                        text_of("egl_device"), text_of("cuda_device"), text_of("gl_renderer"),
                        rank["pieces_done"].get<std::size_t>(), text_of("failure"));
  }
  for (const nlohmann::json& piece : d["retried_or_failed_pieces"])
    text += fmt::format("\n- `{}` {} after: {}", piece["piece"].get<std::string>(),
                        piece["state"].get<std::string>() == "done" ? "finished on another rank" : "failed",
                        piece["errors"].get<std::string>());
  if (!d["retried_or_failed_pieces"].empty()) text += "\n";
  return text + "\n";
}

ProgressOutput rank_progress_output() {
  if (world().lead()) return ProgressOutput::for_stderr();
  static std::ostream nowhere(nullptr);  // no buffer: every write is dropped
  ProgressOutput output;
  output.stream = &nowhere;
  output.plain_interval = std::chrono::hours(24 * 365);
  return output;
}

}  // namespace glint::mpi
