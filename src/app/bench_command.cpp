#include "app/bench_command.h"

#include "accel/builders/builder.h"
#include "rt/blas_structure.h"
#include "app/bench/adaptive_experiment.h"
#include "app/bench/glossy_experiment.h"
#include "app/bench/backend_availability.h"
#include "app/bench/bench_environment.h"
#include "app/bench/bench_report.h"
#include "app/bench/bench_summary.h"
#include "app/bench/fig11_points.h"
#include "app/bench/floor_plan.h"
#include "app/bench/cell_run.h"
#include "app/bench/paper_matrix.h"
#include "app/bench/plot_script.h"
#include "app/bench/resume.h"
#include "app/mpi/bench_share.h"
#include "app/mpi/mpi_world.h"
#include "app/mpi/rank_devices.h"
#include "backends/registry.h"
#include "backends/registry.h"
#include "core/interruption.h"
#include "app/output_folder.h"
#include "app/time_limit.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "core/utc_timestamp.h"
#include "render/raster_settings.h"
#include "render/shadow_method.h"
#include "rt/ray_tracer.h"
#include "gl/egl_context.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <ctime>
#include <map>
#include <optional>

namespace glint {
namespace {

namespace fs = std::filesystem;
using bench::Cell;
using bench::CellKind;
using bench::CellOutcome;

constexpr const char* kExperiments[] = {"paper", "adaptive", "glossy"};

// A cell of this run: what it is, its frames and what became of it.
struct PlannedCell {
  Cell cell;
  std::vector<int> frames;
  CellOutcome outcome;
  bool to_run = false;
};

std::string trimmed(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}


void check_options(const BenchOptions& options) {
  bool known = false;
  for (const char* experiment : kExperiments) known = known || options.experiment == experiment;
  if (!known) fail("--experiment: unknown experiment \"{}\" (known: paper, adaptive, glossy)", options.experiment);
}

// The settings every kept cell must share with this run (resume.h).
nlohmann::json run_settings(const BenchOptions& options) {
  return {{"experiment", options.experiment}, {"scene", options.scene},     {"simple_scene", options.simple_scene},
          {"width", options.width},           {"height", options.height},   {"frames", options.frames},
          {"stride", options.stride},         {"warmup_frames", options.warmup},
          {"shadow_map_size", options.shadow_map_size}, {"gbuffer", options.gbuffer},
          {"shadows", options.shadows}};
}

std::vector<bench::RowKey> expected_rows(const PlannedCell& planned) {
  std::vector<bench::RowKey> rows;
  for (const int frame : planned.frames) {
    if (planned.cell.kind == CellKind::frame_times) {
      rows.push_back({std::to_string(frame)});
      continue;
    }
    for (const char* mode : bench::kComparedModes) rows.push_back({std::to_string(frame), mode});
  }
  return rows;
}

// Skips what cannot run on these scenes and keeps what an earlier run finished.
void plan_cell(PlannedCell& planned, const Scene& scene, const BenchOptions& options, const fs::path& out) {
  const Cell& cell = planned.cell;
  if (cell.skip_reason) {
    planned.outcome = {CellOutcome::State::skipped, *cell.skip_reason};
    return;
  }
  if (cell.deform && scene.deformable_meshes().empty()) {
    planned.outcome = {CellOutcome::State::skipped, fmt::format("scene {} has no deformable meshes", cell.scene)};
    return;
  }
  const int walkthrough_frames = scene.walkthrough.frame_count;
  planned.frames = cell.kind == CellKind::quality ? bench::quality_frames(walkthrough_frames)
                                                  : bench::strided_frames(walkthrough_frames, options.frames, options.stride);
  if (planned.frames.empty()) {
    planned.outcome = {CellOutcome::State::skipped,
                       fmt::format("the walkthrough of {} has {} frames, none of the cell's", cell.scene, walkthrough_frames)};
    return;
  }
  const fs::path csv = bench::cell_csv_path(out, cell);
  if (const std::optional<bench::CsvTable> table = bench::read_csv_table(csv)) {
    const std::optional<std::string> problem =
        bench::finished_cell_problem(*table, bench::cell_csv_header(cell.kind), expected_rows(planned));
    if (!problem) {
      planned.outcome = {CellOutcome::State::done, "", true};
      return;
    }
    log_warning("{}: not a finished cell of this run ({}); measuring it again", csv.string(), *problem);
  }
  planned.to_run = true;
}

void print_final_table(const std::vector<PlannedCell>& cells, const nlohmann::json& summary) {
  fmt::print("{:<34} {:<8} {:>6} {:>10} {:>10} {:>10}\n", "cell", "status", "frames", "mean ms", "median", "p95");
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const nlohmann::json& entry = summary["cells"][i];
    const std::string status = std::string(bench::state_name(cells[i].outcome.state)) + (cells[i].outcome.resumed ? "*" : "");
    if (cells[i].outcome.state != CellOutcome::State::done) {
      fmt::print("{:<34} {:<8} {}\n", cells[i].cell.id, status, cells[i].outcome.reason);
    } else if (cells[i].cell.kind == CellKind::quality) {
      std::string buckets;
      for (const nlohmann::json& row : entry["rows"])
        buckets += fmt::format(" {}@{}={:.2f}%", row["mode"].get<std::string>(), row["frame"].get<int>(),
                               row["buckets_percent"]["mean"].get<double>());
      fmt::print("{:<34} {:<8} {:>6} {}\n", cells[i].cell.id, status, entry["rows"].size() / 2, buckets);
    } else {
      const nlohmann::json& ms = entry["frame_ms"];
      fmt::print("{:<34} {:<8} {:>6} {:>10.2f} {:>10.2f} {:>10.2f}\n", cells[i].cell.id, status,
                 entry["frames"].get<int>(), ms["mean"].get<double>(), ms["median"].get<double>(), ms["p95"].get<double>());
    }
  }
  bool resumed = false;
  for (const PlannedCell& planned : cells) resumed = resumed || planned.outcome.resumed;
  if (resumed) fmt::print("* kept from an earlier run in the same folder\n");
}

}  // namespace

std::vector<std::string> parse_name_list(const std::string& flag, const std::string& text,
                                         const std::vector<std::string>& known) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    const std::string item = trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (item.empty()) fail("{} \"{}\": empty item (expected a comma-separated list)", flag, text);
    if (!known.empty() && std::find(known.begin(), known.end(), item) == known.end())
      fail("{} \"{}\": unknown name \"{}\" (known: {})", flag, text, item, joined(known));
    if (std::find(items.begin(), items.end(), item) != items.end()) fail("{} \"{}\": \"{}\" is listed twice", flag, text, item);
    items.push_back(item);
    if (comma == std::string::npos) return items;
    start = comma + 1;
  }
}

BenchOptions with_quick_defaults(BenchOptions options) {
  if (!options.quick) return options;
  const auto unless_given = [&](const char* flag, auto& value, auto quick_value) {
    if (!options.given.contains(flag)) value = quick_value;
  };
  unless_given("--scene", options.scene, std::string("atrium-simple"));
  unless_given("--simple-scene", options.simple_scene, std::string("atrium-simple"));
  unless_given("--backends", options.backends, std::string("cpu"));
  unless_given("--accels", options.accels, std::string("sah"));
  unless_given("--updates", options.updates, std::string("refit"));
  unless_given("--stride", options.stride, 1225);  // frames 0, 1225, 2450, 3675 of the 4900
  unless_given("--width", options.width, 96);
  unless_given("--height", options.height, 54);
  unless_given("--warmup", options.warmup, 1);
  unless_given("--interval", options.interval, 2);
  unless_given("--shadow-map-size", options.shadow_map_size, 128);
  unless_given("--reference-spp", options.reference_spp, 16);
  unless_given("--flicker-frames", options.flicker_frames, 3);
  // glossy: the first quality frame only (1800), each of its configurations rendering 3 x 3 + 2 frames.
  if (options.experiment == "glossy") unless_given("--frames", options.frames, 1801);
  return options;
}

void add_bench_command(CLI::App& app, BenchOptions& options) {
  CLI::App* command = app.add_subcommand(
      "bench", "Run the paper's experiment matrix (Figs. 5, 7-10, 12, Tables I-II): CSVs, summary.json, charts, report.md");
  command->add_option("--experiment", options.experiment,
                      "Experiment to run: paper, adaptive (quality vs reflection cost of ssr, hybrid, rt and auto) "
                      "or glossy (glossy ssr, hybrid, rt with and without the denoiser against the converged "
                      "reference: SSIM, PSNR, cost, flicker); docs/bench.md")
      ->required();
  command->add_option("--scene", options.scene, "Full scene (Figs. 5, 7, Table I): atrium, sponza or a scene file")
      ->capture_default_str();
  command->add_option("--simple-scene", options.simple_scene,
                      "Simplified scene (Figs. 8, 9, 10, 12, Table II): atrium-simple or a scene file")
      ->capture_default_str();
  command->add_option("--backends", options.backends,
                      "Ray tracing backends, comma-separated: " + fmt::format("{}", fmt::join(backends::backend_names(), ", ")) +
                          " (unavailable ones are reported as skipped)")
      ->capture_default_str();
  command->add_option("--accels", options.accels,
                      "Structures of the " + backends::builder_backends_text() +
                          " backends, comma-separated (the others build their own)")
      ->capture_default_str();
  command->add_option("--updates", options.updates, "Update policies of the deforming cells: rebuild, refit, auto")
      ->capture_default_str();
  command->add_option("--frames", options.frames,
                      "Walkthrough frames considered: 0 .. N-1 (the paper: 4900; adaptive and glossy: their quality "
                      "frames 1800, 2100, 2300, 4400 below N)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--stride", options.stride, "Measure every K-th of those frames")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--width", options.width, "Image width in pixels")->check(CLI::Range(16, 16384))->capture_default_str();
  command->add_option("--height", options.height, "Image height in pixels")->check(CLI::Range(16, 16384))->capture_default_str();
  command->add_option("--warmup", options.warmup, "Unrecorded frames rendered before each cell's measured ones")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command->add_option("--interval", options.interval, "Measured frames per interval mean (the paper: 10)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  command->add_option("--shadow-map-size", options.shadow_map_size, "Shadow cube map face size in texels")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  command->add_option("--gbuffer", options.gbuffer, "How the G-buffer is made: raster or visibility (as glint render)")
      ->check(CLI::IsMember(render::kGBufferMethodNames.names()))
      ->capture_default_str();
  command
      ->add_option("--shadows", options.shadows, "How the light's shadow is made: cube, rt or hybrid (as glint render)")
      ->check(CLI::IsMember(render::kShadowMethodNames.names()))
      ->capture_default_str();
  command->add_option("--reference-spp", options.reference_spp,
                      "glossy: reflection samples per pixel of the converged reference (rt, --denoise off), "
                      "cached in DIR/references")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  command->add_option("--flicker-frames", options.flicker_frames,
                      "glossy: frames of each flicker series: the walkthrough frames up to each measured frame, "
                      "then as many held still (camera, light, meshes) as warm-up and as many measured")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  command->add_flag("--quick", options.quick,
                    "Smoke run: 96x54, 4 frames per cell, cpu backend, sah, refit, atrium-simple; glossy: frame 1800 only, "
                    "a 16-sample reference, 3 flicker frames (flags given explicitly still apply)");
  command->add_flag("--no-plot", options.no_plot, "Do not run tools/plot_bench.py (report.md says how to)");
  command->add_option("--time-limit", options.time_limit,
                      "paper: start no cell (under mpirun: no piece) once this long has passed since the start, "
                      "e.g. 7h or 50m or 600 (seconds); the cells under way finish and are kept, the run exits "
                      "with 75 and the same command resumes it")
      ->check(CLI::Validator(
          [](std::string& text) {
            try {
              parse_time_limit_seconds("--time-limit", text);
              return std::string();
            } catch (const Error& error) {
              return std::string(error.what());
            }
          },
          "DURATION"));
  command->add_option("--out", options.out, "Output folder (created if missing; a run in it is resumed)")->required();
  command->callback([command, &options] {
    for (const char* flag : {"--scene", "--simple-scene", "--backends", "--accels", "--updates", "--frames", "--stride",
                             "--width", "--height", "--warmup", "--interval", "--shadow-map-size", "--reference-spp",
                             "--flicker-frames"})
      if (command->count(flag) > 0) options.given.insert(flag);
  });
}

int run_bench_command(const BenchOptions& given_options) {
  // Under mpirun: this rank's GPU, chosen before any GL or CUDA call (nothing changes with one rank).
  mpi::RankSession rank;
  const BenchOptions options = with_quick_defaults(given_options);
  check_options(options);
  const TimeLimit time_limit = TimeLimit::from_flag("--time-limit", options.time_limit);
  if (!options.time_limit.empty() && options.experiment != "paper")
    fail("--time-limit: only --experiment paper keeps its finished cells to resume from");
  if (options.experiment == "adaptive") return bench::run_adaptive_experiment(options);
  if (options.experiment == "glossy") return bench::run_glossy_experiment(options);
  const std::vector<std::string> known_backends = backends::backend_names();
  const std::vector<std::string> known_accels = rt::blas_structure_names();
  const std::vector<std::string> backends = parse_name_list("--backends", options.backends, known_backends);
  const std::vector<std::string> accels = parse_name_list("--accels", options.accels, known_accels);
  const std::vector<std::string> updates = parse_name_list("--updates", options.updates, rt::kUpdatePolicyNames.names());
  const fs::path out = options.out;
  const nlohmann::json settings = run_settings(options);
  // Before anything is written: a folder holding another run's cells is not mixed with this one.
  if (fs::is_directory(out)) bench::check_run_settings(out, settings);

  bench::MatrixOptions matrix;
  matrix.scene = options.scene;
  matrix.simple_scene = options.simple_scene;
  matrix.structures = bench::structures_of(backends, accels);
  matrix.updates = updates;
  nlohmann::json backend_entries = nlohmann::json::array();
  for (const std::string& backend : backends) {
    const std::optional<std::string> reason = bench::backend_unavailable_reason(backend);
    if (reason) matrix.unavailable_backends[backend] = *reason;
    backend_entries.push_back(reason ? nlohmann::json{{"name", backend}, {"available", false}, {"reason", *reason}}
                                     : nlohmann::json{{"name", backend}, {"available", true}});
  }

  std::map<std::string, Scene> scenes;
  for (const std::string& name : {options.scene, options.simple_scene})
    if (!scenes.contains(name)) scenes.emplace(name, load_scene(name));
  std::vector<PlannedCell> cells;
  for (Cell& cell : bench::paper_matrix(matrix)) {
    PlannedCell& planned = cells.emplace_back();
    planned.cell = std::move(cell);
    plan_cell(planned, scenes.at(planned.cell.scene), options, out);
  }

  const OutputFolder folder(out);
  if (mpi::world().lead()) {  // the one process, or rank 0 of an mpirun before any rank writes
    if (const std::size_t stale = remove_stale_temporaries(out); stale > 0)
      log_warning("bench: removed {} temporary file(s) an earlier, killed run left in {}", stale, out.string());
    bench::write_run_settings(out, settings);
  }
  HeadlessGlContext context;
  const bench::CellRunSettings cell_settings{options.width, options.height, options.warmup, options.shadow_map_size,
                                             options.command_line, options.gbuffer, options.shadows};
  std::size_t ticks = 0;
  for (const PlannedCell& planned : cells)
    if (planned.to_run) ticks += bench::cell_ticks(planned.cell, planned.frames.size(), cell_settings);
  ProgressBar progress("bench", ticks, mpi::rank_progress_output());
  // Ctrl-C or SIGTERM stops the cell under way (its temporaries are removed as the stack unwinds);
  // the finished cells' files stay, and the same command resumes from them.
  const InterruptionScope interruptible;
  nlohmann::json distribution;  // how an mpirun shared the cells (app/mpi/bench_share.h)
  if (mpi::world().size > 1) {
    std::vector<mpi::BenchCellPlan> plans;
    for (const PlannedCell& planned : cells) plans.push_back({&planned.cell, &planned.frames, planned.to_run});
    const std::optional<mpi::SharedBenchRun> shared =
        mpi::run_bench_shared(plans, scenes, cell_settings, context, out, progress, rank.about(), time_limit.until());
    if (!shared) return 0;  // rank 0 writes the summary
    rank.shared_work_over();  // every other rank has stopped or retired
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (shared->outcomes[i]) {
        cells[i].outcome = *shared->outcomes[i];
        cells[i].to_run = false;
      }
    distribution = shared->distribution;
    if (shared->time_limit_reached) {
      std::size_t finished = 0;
      for (const PlannedCell& planned : cells)
        finished += planned.outcome.state == CellOutcome::State::done && !planned.to_run ? 1 : 0;
      progress.finish();
      throw TimeLimitReached(fmt::format("bench: the time limit ({}) has passed; {} of {} cells are done in {} (and the "
                                         "finished ranges of split cells in cells/parts/); the same command resumes the run",
                                         time_limit.text(), finished, cells.size(), out.string()));
    }
    // mpirun passes a Ctrl-C or SIGTERM to every rank: the cells left are interrupted, not failed,
    // and, as in one process, no summary is written until the same command has run them.
    if (interruption_requested()) {
      std::size_t finished = 0;
      for (const PlannedCell& planned : cells)
        finished += planned.outcome.state == CellOutcome::State::done ? 1 : 0;
      progress.finish();
      throw Interrupted(fmt::format("bench: interrupted by {}; {} of {} cells are done in {} (and the finished ranges "
                                    "of split cells in cells/parts/); the same command resumes the run",
                                    interruption_signal_name(), finished, cells.size(), out.string()));
    }
  }
  std::size_t done = 0;
  for (const PlannedCell& planned : cells) done += planned.outcome.resumed ? 1 : 0;
  for (PlannedCell& planned : cells) {
    if (!planned.to_run) continue;
    if (time_limit.passed()) {
      progress.finish();
      throw TimeLimitReached(fmt::format("bench: the time limit ({}) has passed; {} of {} cells are done in {}; the same "
                                         "command resumes the run",
                                         time_limit.text(), done, cells.size(), out.string()));
    }
    try {
      bench::run_cell(planned.cell, scenes.at(planned.cell.scene), planned.frames, cell_settings, context, out, progress);
      planned.outcome = {CellOutcome::State::done, "", false};
      ++done;
    } catch (const Interrupted&) {
      progress.finish();
      throw Interrupted(fmt::format("bench: interrupted by {} in cell {}; {} of {} cells are done in {}; the same "
                                    "command resumes the run",
                                    interruption_signal_name(), planned.cell.id, done, cells.size(), out.string()));
    } catch (const Error& error) {
      planned.outcome = {CellOutcome::State::failed, error.what(), false};
      log_warning("bench: cell {} failed: {}", planned.cell.id, error.what());
    }
  }
  progress.finish();

  nlohmann::json summary_settings = settings;
  summary_settings["interval_frames"] = options.interval;
  summary_settings["quick"] = options.quick;
  nlohmann::json summary = {{"experiment", options.experiment},
                            {"command", options.command_line},
                            {"environment", bench::describe_environment(context)},
                            {"settings", summary_settings},
                            {"backends", backend_entries},
                            {"cells", nlohmann::json::array()}};
  for (const PlannedCell& planned : cells)
    summary["cells"].push_back(
        bench::cell_summary(planned.cell, planned.outcome, out, static_cast<std::size_t>(options.interval)));
  summary["fig11"] = bench::fig11_points(summary["cells"]);
  if (!distribution.is_null()) summary["distribution"] = distribution;
  summary["floor_plan"] = bench::floor_plan_json(scenes.at(options.scene), options.scene);
  bench::write_summary(out, summary);

  std::string chart_note = options.no_plot ? fmt::format("charts not made (--no-plot); run: python3 {} {}",
                                                         (out / "plot_bench.py").string(), out.string())
                                           : bench::plot_bench_charts(out);
  if (options.no_plot) write_file_atomically(out / "plot_bench.py", bench::kPlotBenchScript);
  if (!chart_note.empty()) log_warning("{}", chart_note);
  write_file_atomically(out / "report.md", bench::bench_report_markdown(summary, out, {utc_timestamp(), chart_note}));

  print_final_table(cells, summary);
  std::size_t failed = 0;
  for (const PlannedCell& planned : cells) failed += planned.outcome.state == CellOutcome::State::failed ? 1 : 0;
  if (failed > 0) fail("{} of {} cells failed (reasons in {})", failed, cells.size(), (out / "summary.json").string());
  return 0;
}

}  // namespace glint
