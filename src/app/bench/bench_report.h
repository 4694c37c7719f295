#pragma once
// report.md of a `glint bench` run, generated from summary.json: where and how it was measured
// (device, driver, glint version and commit, command line, resolution, frames and stride), one
// section per figure and table with the paper's numbers beside glint's, the charts that
// tools/plot_bench.py made, and every skipped or failed cell with its reason.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::bench {

struct ReportExtras {
  std::string date;        // UTC, ISO 8601
  std::string chart_note;  // "" when the charts were made; otherwise why not and how to make them
};

// The report's Markdown text. `out` is the run's folder: charts are linked when charts/<name>.png exists.
std::string bench_report_markdown(const nlohmann::json& summary, const std::filesystem::path& out,
                                  const ReportExtras& extras);

}  // namespace glint::bench
