#include "app/bench/resume.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace glint::bench {
namespace {

constexpr const char* kSettingsFile = "bench_settings.json";

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

bool is_number(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  (void)std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

}  // namespace

std::optional<CsvTable> read_csv_table(const std::filesystem::path& path) {
  std::ifstream file(path);
  if (!file) return std::nullopt;
  CsvTable table;
  std::string line;
  if (!std::getline(file, line)) return std::nullopt;
  table.header = split_fields(line);
  while (std::getline(file, line))
    if (!line.empty()) table.rows.push_back(split_fields(line));
  return table;
}

std::optional<std::string> finished_cell_problem(const CsvTable& table, const std::vector<std::string>& header,
                                                 const std::vector<RowKey>& rows) {
  if (table.header != header) return std::string("its header differs from this glint's");
  if (table.rows.size() != rows.size()) return fmt::format("{} rows, expected {}", table.rows.size(), rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const std::vector<std::string>& row = table.rows[r];
    if (row.size() != header.size()) return fmt::format("row {} has {} fields, expected {}", r + 1, row.size(), header.size());
    for (std::size_t k = 0; k < rows[r].size(); ++k)
      if (row[k] != rows[r][k]) return fmt::format("row {} starts with {}, expected {}", r + 1, row[k], rows[r][k]);
    for (std::size_t column = rows[r].size(); column < row.size(); ++column)
      if (!row[column].empty() && !is_number(row[column]))
        return fmt::format("row {}, column {}: '{}' is not a number", r + 1, header[column], row[column]);
  }
  return std::nullopt;
}

void check_run_settings(const std::filesystem::path& folder, const nlohmann::json& settings) {
  const std::filesystem::path path = folder / kSettingsFile;
  std::ifstream file(path);
  if (!file) return;
  std::stringstream text;
  text << file.rdbuf();
  const nlohmann::json previous = nlohmann::json::parse(text.str(), nullptr, false);
  if (previous.is_discarded() || !previous.is_object())
    fail("{}: not a JSON object; remove it (or the folder) to start this run afresh", path.string());
  for (const auto& [key, value] : settings.items()) {
    const nlohmann::json before = previous.contains(key) ? previous[key] : nlohmann::json();
    if (before != value)
      fail("{}: this folder holds a run with {} {}, this run has {}; use another --out to keep both", path.string(), key,
           before.dump(), value.dump());
  }
}

void write_run_settings(const std::filesystem::path& folder, const nlohmann::json& settings) {
  const std::filesystem::path path = folder / kSettingsFile;
  if (!std::filesystem::exists(path)) write_file_atomically(path, settings.dump(2) + "\n");
}

}  // namespace glint::bench
