#include "app/bench/bench_summary.h"

#include "app/bench/cell_run.h"
#include "app/bench/frame_time_statistics.h"
#include "app/bench/resume.h"
#include "core/atomic_file.h"
#include "core/error.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace glint::bench {
namespace {

// JSON has no infinity or NaN: PSNR of identical images is written as the string "inf" (as `glint compare` does).
nlohmann::json json_number(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  return value;
}

std::size_t column_of(const CsvTable& table, const std::string& name) {
  for (std::size_t i = 0; i < table.header.size(); ++i)
    if (table.header[i] == name) return i;
  fail("bench: column {} missing", name);
}

// The non-empty values of one column.
std::vector<double> column_values(const CsvTable& table, const std::string& name) {
  const std::size_t column = column_of(table, name);
  std::vector<double> values;
  for (const auto& row : table.rows)
    if (!row[column].empty()) values.push_back(std::stod(row[column]));
  return values;
}

nlohmann::json series_json(const SeriesSummary& s) {
  return {{"mean", s.mean}, {"median", s.median}, {"p5", s.p5}, {"p95", s.p95}, {"min", s.min}, {"max", s.max}};
}

nlohmann::json mean_or_null(const std::vector<double>& values) {
  if (values.empty()) return nullptr;
  return summarize(values).mean;
}

void add_frame_time_statistics(nlohmann::json& entry, const CsvTable& table, std::size_t interval) {
  std::vector<int> frames;
  for (const auto& row : table.rows) frames.push_back(std::stoi(row[0]));
  const std::vector<double> frame_ms = column_values(table, "frame_ms");
  entry["frames"] = frames.size();
  entry["first_frame"] = frames.front();
  entry["last_frame"] = frames.back();
  entry["frame_ms"] = series_json(summarize(frame_ms));
  entry["frame_latency_ms"] = series_json(summarize(column_values(table, "frame_latency_ms")));
  entry["gpu_total_ms"] = series_json(summarize(column_values(table, "gpu_total_ms")));
  entry["mean_ms"] = {{"deform", mean_or_null(column_values(table, "deform_ms"))},
                      {"accel_update", mean_or_null(column_values(table, "accel_update_ms"))},
                      {"trace", mean_or_null(column_values(table, "trace_ms"))}};
  entry["mean_rays_traced"] = mean_or_null(column_values(table, "rays_traced"));
  entry["mean_reflective_pixels"] = mean_or_null(column_values(table, "reflective_pixels"));
  nlohmann::json intervals = nlohmann::json::array();
  for (const IntervalMean& mean : interval_means(frames, frame_ms, interval))
    intervals.push_back({{"first_frame", mean.first_frame}, {"last_frame", mean.last_frame}, {"mean_ms", mean.mean_ms}});
  entry["interval_frames"] = interval;
  entry["intervals"] = intervals;
}

void add_quality_rows(nlohmann::json& entry, const CsvTable& table) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& row : table.rows)
    rows.push_back({{"frame", std::stoi(row[0])},
                    {"mode", row[1]},
                    {"buckets_percent",
                     {{"r", std::stod(row[2])}, {"g", std::stod(row[3])}, {"b", std::stod(row[4])}, {"mean", std::stod(row[5])}}},
                    {"ssim_luma", std::stod(row[6])},
                    {"rmse", std::stod(row[7])},
                    {"psnr_db", json_number(std::stod(row[8]))}});
  entry["rows"] = rows;
}

nlohmann::json read_side_file(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) return nullptr;
  std::stringstream text;
  text << file.rdbuf();
  const nlohmann::json side = nlohmann::json::parse(text.str(), nullptr, false);
  return side.is_discarded() ? nlohmann::json(nullptr) : side;
}

}  // namespace

nlohmann::json cell_summary(const Cell& cell, const CellOutcome& outcome, const std::filesystem::path& out,
                            std::size_t interval) {
  nlohmann::json entry = {{"id", cell.id},
                          {"figure", cell.figure},
                          {"kind", cell.kind == CellKind::quality ? "quality" : "frame_times"},
                          {"scene", cell.scene},
                          {"reflections", cell.reflections},
                          {"backend", cell.structure.backend},
                          {"accel", cell.structure.accel},
                          {"structure", cell.structure.backend.empty() ? "" : cell.structure.label()},
                          {"update", cell.update},
                          {"deform", cell.deform},
                          {"traced", cell.trace_deformable_only ? "deformable instances" : "all instances"},
                          {"status", state_name(outcome.state)}};
  if (outcome.state != CellOutcome::State::done) {
    entry["reason"] = outcome.reason;
    return entry;
  }
  const std::filesystem::path csv_path = cell_csv_path(out, cell);
  const std::optional<CsvTable> table = read_csv_table(csv_path);
  if (!table || table->rows.empty()) fail("{}: cannot read the finished cell's table", csv_path.string());
  entry["csv"] = std::filesystem::relative(csv_path, out).string();
  if (cell.kind == CellKind::quality) {
    add_quality_rows(entry, *table);
    entry["images"] = std::filesystem::relative(cell_image_folder(out, cell), out).string();
  } else {
    add_frame_time_statistics(entry, *table, interval);
  }
  const nlohmann::json side = read_side_file(cell_json_path(out, cell));
  if (side.is_object()) {
    if (side.contains("scene")) entry["scene_stats"] = side["scene"];
    for (const char* key : {"ray_tracer", "warmup_frames", "wall_seconds", "pieces"})  // pieces: app/mpi/bench_share.h
      if (side.contains(key)) entry[key] = side[key];
  }
  return entry;
}

void write_summary(const std::filesystem::path& out, const nlohmann::json& summary) {
  write_file_atomically(out / "summary.json", summary.dump(2) + "\n");
}

}  // namespace glint::bench
