#pragma once
// `glint compare A.png B.png`: how close a rendered image is to a reference (by default B, the
// ray-traced one): the paper's colour buckets, SSIM, RMSE, PSNR as a table, optionally as JSON and
// a per-pixel error heat map (docs/metrics.md). Two linear EXRs (`glint render --format exr`) are
// compared in linear space (RMSE, PSNR against the reference's peak, SSIM on luminance) and as the
// 8-bit pictures the renderer's tone map makes of them (render/tone_map.h), with the same numbers.
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
  // EXRs: the tone map that makes their 8-bit pictures; empty: each file's own (the renderer records
  // it, render::kExrToneMapAttribute), aces when it has none.
  std::string tone_map;
};

void add_compare_command(CLI::App& app, CompareOptions& options);
int run_compare_command(const CompareOptions& options);

}  // namespace glint
