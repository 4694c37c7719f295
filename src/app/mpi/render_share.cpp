#include "app/mpi/render_share.h"

#include "app/frame_loop.h"
#include "app/mpi/bench_share.h"
#include "app/mpi/mpi_world.h"
#include "app/mpi/work_share.h"
#include "app/output_folder.h"
#include "app/frame_image_files.h"
#include "app/image_writer_thread.h"
#include "app/render_run_record.h"
#include "app/video_writer.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/image.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "core/stopwatch.h"
#include "gl/egl_context.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <string_view>

namespace glint::mpi {
namespace {

constexpr int kFolderTag = 2403;  // 0 -> rank: "" when --out is ready, else rank 0's error
constexpr std::size_t kPiecesPerRank = 8;

std::vector<std::string> row_texts(const std::vector<CsvField>& row) {
  std::vector<std::string> texts;
  texts.reserve(row.size());
  for (const CsvField& field : row) texts.push_back(field.text());
  return texts;
}

// Rank 0 prepares --out as one process does; the others wait for it, then share it as it is.
// nullopt on a rank other than 0 when rank 0 could not (its error is rank 0's to print).
std::optional<std::filesystem::path> prepare_folder(const RenderOptions& options, std::optional<OutputFolder>& folder) {
  const Rank& rank = world();
  if (rank.lead()) {
    std::string error;
    try {
      folder.emplace(options.out, options.overwrite ? EarlierRun::replace : EarlierRun::refuse);
    } catch (const Error& e) {
      error = e.what();
    }
    for (int other = 1; other < rank.size; ++other) send_text(other, kFolderTag, error);
    if (!error.empty()) throw Error(error);
    return folder->path();
  }
  if (!receive_text(0, kFolderTag).text.empty()) return std::nullopt;
  folder.emplace(options.out, EarlierRun::keep);
  return folder->path();
}

}  // namespace

std::size_t render_piece_frames(std::size_t frames, int ranks) {
  if (const char* value = std::getenv("GLINT_MPI_PIECE_FRAMES"); value != nullptr && *value != '\0') {
    const std::string_view text(value);
    std::size_t count = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
    if (error != std::errc() || end != text.data() + text.size() || count == 0)
      fail("GLINT_MPI_PIECE_FRAMES={}: expected a positive number of frames", text);
    return count;
  }
  const std::size_t pieces = kPiecesPerRank * static_cast<std::size_t>(std::max(ranks, 1));
  return std::max<std::size_t>(1, (frames + pieces - 1) / pieces);
}

int run_render_shared(const RenderOptions& options, const RenderOptions& recorded,
                      const render::FramePipelineSettings& settings, Scene& scene, const std::vector<int>& frames,
                      const nlohmann::json& about) {
  std::optional<OutputFolder> folder;
  if (!prepare_folder(options, folder)) return 1;
  const OutputFolder& out = *folder;
  const Stopwatch run_watch;
  HeadlessGlContext context;
  const bool images = !options.timings_only;
  // As run_render_command's loop.
  FrameLoopOptions loop_options{options.width, options.height, options.deform == "on", deforms_on_gpu(options)};
  set_image_capture(options, loop_options);
  loop_options.serialized = options.debug_views;
  loop_options.profile_scopes = options.profile_scopes;
  if (options.hold_frame >= 0) loop_options.hold_frame = options.hold_frame;
  FrameLoop loop(scene, settings, loop_options, pass_timing_for_renderer(context.renderer()));
  render::FramePipeline& pipeline = loop.pipeline();
  // This rank's rows; rank 0 records every rank's in the run's record below.
  RenderRunRecord rank_record(recorded, scene, context, loop.pass_timing(), frames);

  const std::size_t per_piece = render_piece_frames(frames.size(), world().size);
  const std::size_t piece_count = (frames.size() + per_piece - 1) / per_piece;
  const auto piece_range = [&](std::size_t piece) {
    const std::size_t first = piece * per_piece;
    return std::pair{first, std::min(frames.size(), first + per_piece)};
  };
  ProgressBar progress("render", frames.size(), rank_progress_output());
  nlohmann::json rank_about = about;
  rank_about["gl_renderer"] = context.renderer();

  const auto run = [&](std::size_t piece) -> nlohmann::json {
    const auto [first, end] = piece_range(piece);
    nlohmann::json rows = nlohmann::json::array(), scopes = nlohmann::json::array();
    // The piece's images are on disk before it counts as done (rank 0 reads the PNGs for the video).
    std::optional<ImageWriterThread> image_writer;
    if (images) image_writer.emplace();
    const auto keep = [&](FrameMeasurement& measured) {
      if (image_writer) write_frame_image_files(*image_writer, out, options, measured, pipeline);
      rows.push_back(row_texts(rank_record.add_frame(measured)));
      for (const ScopeTime& scope : measured.scopes)
        scopes.push_back(row_texts({measured.frame, scope.path, scope.depth, scope.milliseconds}));
      progress.tick();
    };
    for (std::size_t i = first; i < end; ++i)
      for (FrameMeasurement& measured : loop.submit(frames[i])) keep(measured);
    for (FrameMeasurement& measured : loop.drain()) keep(measured);
    if (image_writer) image_writer->finish();
    nlohmann::json result = {{"rows", rows},
                             {"scopes", scopes},
                             {"rank", world().rank},
                             {"primary_visibility", primary_visibility_record(pipeline.raster())}};
    if (const rt::RayTracer* tracer = pipeline.ray_tracer()) {
      const rt::RayTracerStats stats = tracer->stats();
      result["tracer"] = {{"rebuilds", stats.rebuilds}, {"refits", stats.refits}};  // this rank's, so far
    }
    return result;
  };
  // Started before the frames, as one process starts it (ffmpeg missing is one line before any frame);
  // rank 0 feeds it the PNGs in frame order once every piece is done.
  std::optional<FfmpegVideoWriter> video;
  if (options.video && world().lead())
    video.emplace(out.path() / "walkthrough.mp4", options.width, options.height, scene.walkthrough.frames_per_second);
  WorkShareOptions share_options;
  share_options.errors_retire_rank = true;  // a frame that failed leaves the loop in no state to go on
  const std::optional<ShareResult> shared =
      share_pieces(piece_count, run, rank_about, share_options, [&](std::size_t piece) {
        const auto [first, end] = piece_range(piece);
        progress.tick(end - first);
      });
  if (!shared) return 0;  // rank 0 writes the run's files
  progress.finish();

  std::string failures;
  for (std::size_t piece = 0; piece < piece_count; ++piece) {
    if (shared->pieces[piece].state == PieceScheduler::State::done) continue;
    const auto [first, end] = piece_range(piece);
    std::string errors;
    for (const PieceScheduler::Attempt& attempt : shared->pieces[piece].attempts)
      errors += fmt::format("{}rank {}: {}", errors.empty() ? "" : "; ", attempt.rank, attempt.error);
    failures += fmt::format("{}frames {}-{} ({})", failures.empty() ? "" : "; ", frames[first], frames[end - 1], errors);
  }
  if (!failures.empty())
    fail("render: no rank could render {}; the frames written are in {}", failures, out.path().string());

  // The run's record: every frame in order, as one process records them.
  RenderRunRecord record(recorded, scene, context, loop.pass_timing(), frames);
  std::optional<rt::RayTracerStats> tracer_stats;
  if (pipeline.ray_tracer() != nullptr) {
    tracer_stats = pipeline.ray_tracer()->stats();
    record.set_ray_tracer(settings.ray_tracing, *tracer_stats);
    // Each rank built its own structures and updated them over its frames: the counts add up.
    std::vector<nlohmann::json> last_of_rank(shared->ranks.size());
    for (const nlohmann::json& result : shared->results)
      if (result.contains("tracer")) last_of_rank.at(result["rank"].get<std::size_t>()) = result["tracer"];
    tracer_stats->rebuilds = tracer_stats->refits = 0;
    for (const nlohmann::json& counts : last_of_rank)
      if (counts.is_object()) {
        tracer_stats->rebuilds += counts["rebuilds"].get<std::size_t>();
        tracer_stats->refits += counts["refits"].get<std::size_t>();
      }
  }
  CsvWriter timings(out.path() / "timings.csv", RenderRunRecord::timings_header());
  std::optional<CsvWriter> scopes;
  if (options.profile_scopes)
    scopes.emplace(out.path() / "scopes.csv", std::vector<std::string>{"frame", "scope", "depth", "ms"});
  nlohmann::json pieces = nlohmann::json::array();
  for (std::size_t piece = 0; piece < piece_count; ++piece) {
    const nlohmann::json& result = shared->results[piece];
    for (const nlohmann::json& row : result["rows"]) {
      const std::vector<std::string> fields = row.get<std::vector<std::string>>();
      record.add_row(fields);
      timings.add_row(std::vector<CsvField>(fields.begin(), fields.end()));
    }
    if (scopes)
      for (const nlohmann::json& row : result["scopes"]) {
        const std::vector<std::string> fields = row.get<std::vector<std::string>>();
        scopes->add_row(std::vector<CsvField>(fields.begin(), fields.end()));
      }
    const auto [first, end] = piece_range(piece);
    pieces.push_back({{"frames", {frames[first], frames[end - 1]}}, {"rank", result["rank"]}});
  }
  if (video) {
    for (const int frame : frames) video->add_frame(read_png(out.frame_path(frame)));
    video->finish();
  }
  timings.commit();
  if (scopes) scopes->commit();
  nlohmann::json ranks = nlohmann::json::array();
  for (const RankReport& report : shared->ranks) {
    nlohmann::json entry = report.about.is_object() ? report.about : nlohmann::json::object();
    entry["rank"] = report.rank;
    entry["pieces_done"] = report.pieces_done;
    // Each rank chose its own with --primary auto (its GPU may differ); the last piece it did says which.
    for (const nlohmann::json& result : shared->results)
      if (result.is_object() && result["rank"] == report.rank) entry["primary_visibility"] = result["primary_visibility"];
    if (report.failure) {
      entry["failure"] = *report.failure;
      log_warning("render: rank {} failed ({}); its frames were rendered by the others", report.rank, *report.failure);
    }
    ranks.push_back(entry);
  }
  record.add_entry("distribution", {{"ranks", world().size},
                                    {"piece_frames", per_piece},
                                    {"note", "each rank renders its pieces through one frame loop: its first frame "
                                             "pays for shader compilation and its own structure build"},
                                    {"per_rank", ranks},
                                    {"pieces", pieces}});
  record.set_primary_visibility(pipeline.raster());
  record.write(out.path() / "run.json", run_watch.elapsed_ms(), tracer_stats);
  log_info("wrote {} frames to {} ({} ranks)", frames.size(), out.path().string(), world().size);
  return 0;
}

}  // namespace glint::mpi
