#pragma once
// How `glint bench` resumes an interrupted run. Every finished cell leaves cells/<id>.csv, written
// atomically (core/atomic_file.h), so the file is there whole or not at all; the next run with the
// same --out keeps every cell whose CSV is present and well-formed (the expected header, the
// expected frames in order, numbers where numbers belong) and runs the others. A side file
// cells/<id>.json, written just before the CSV, keeps what the CSV cannot (build time, memory).
//
// The cells' numbers only compare when the run's settings (scenes, resolution, frames) are the
// same, so the first run writes them to bench_settings.json and a later run with other settings
// stops with one line before writing anything.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint::bench {

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// The table in `path`, split on ',' (bench CSVs hold numbers and plain words, never quotes); nullopt
// when the file is missing or unreadable.
std::optional<CsvTable> read_csv_table(const std::filesystem::path& path);

// One expected row of a finished cell: the leading fields it must start with (frame, mode ...);
// every field after them must be empty or a number ("inf" and "nan" count: PSNR of equal images).
using RowKey = std::vector<std::string>;

// Why the table is not a finished cell's (first difference found), or nullopt when it is.
std::optional<std::string> finished_cell_problem(const CsvTable& table, const std::vector<std::string>& header,
                                                 const std::vector<RowKey>& rows);

// The settings that must match for cells to be kept: checks `folder`/bench_settings.json against
// `settings` (glint::Error naming the first different key and both values, before anything is
// written) and writes it when absent.
void check_run_settings(const std::filesystem::path& folder, const nlohmann::json& settings);
// Writes bench_settings.json (atomically) when absent.
void write_run_settings(const std::filesystem::path& folder, const nlohmann::json& settings);

}  // namespace glint::bench
