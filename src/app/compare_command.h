#pragma once
// `glint compare A.png B.png`: how close a rendered image is to a reference (by default B, the
// ray-traced one): the paper's colour buckets, SSIM, RMSE, PSNR as a table, optionally as JSON and
// a per-pixel error heat map (docs/metrics.md).
#include <CLI/CLI.hpp>

#include <string>

namespace glint {

struct CompareOptions {
  std::string first;             // A
  std::string second;            // B
  std::string reference = "B";   // which of A and B is the reference; the other is the test image
  std::string heatmap;           // PNG path, empty for none
  double heatmap_scale = 64.0;   // luma difference shown as white
  std::string json;              // JSON path, empty for none
};

void add_compare_command(CLI::App& app, CompareOptions& options);
int run_compare_command(const CompareOptions& options);

}  // namespace glint
