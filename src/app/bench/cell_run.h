#pragma once
// Running one cell of `glint bench` (paper_matrix.h) on the current GL context, through the same
// FrameLoop and render settings as `glint render`, and writing its files:
//   frame-times cell:  cells/<id>.json (tracer build, memory, wall time), then cells/<id>.csv with
//                      one timings.csv row per measured frame (RenderRunRecord's columns)
//   quality cell:      cells/<id>/frame_NNNNN_{rt,ssr,hybrid}.png, cells/<id>.json, then
//                      cells/<id>.csv (frame, mode, colour buckets, SSIM, RMSE, PSNR against rt)
// The CSV comes last and atomically: its presence marks the cell finished (resume.h).
#include "app/bench/paper_matrix.h"
#include "core/progress_bar.h"
#include "gl/egl_context.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glint::bench {

struct CellRunSettings {
  int width = 1280;
  int height = 720;
  int warmup_frames = 3;       // rendered before the measured frames, not recorded
  int shadow_map_size = 1024;
  std::string command_line;    // for the render settings' record
  std::string gbuffer = "raster";  // glint render --gbuffer
  std::string shadows = "cube";    // glint render --shadows
};

// cells/<id>.csv, cells/<id>.json and (quality cells) the folder of images.
std::filesystem::path cell_csv_path(const std::filesystem::path& out, const Cell& cell);
std::filesystem::path cell_json_path(const std::filesystem::path& out, const Cell& cell);
std::filesystem::path cell_image_folder(const std::filesystem::path& out, const Cell& cell);

// The CSV header of each kind of cell.
std::vector<std::string> cell_csv_header(CellKind kind);
// The modes a quality cell compares with the rt reference, in CSV order.
inline constexpr const char* kComparedModes[] = {"ssr", "hybrid"};

// Progress ticks the cell takes for `frames` (warm-up and measured frames, or three modes each).
std::size_t cell_ticks(const Cell& cell, std::size_t frames, const CellRunSettings& settings);

// Renders the cell's frames of `scene` (a fresh copy of the loaded scene: deforming poses it) and
// writes its files under `out`. glint::Error when the cell cannot be set up or a frame fails.
void run_cell(const Cell& cell, Scene scene, const std::vector<int>& frames, const CellRunSettings& settings,
              const HeadlessGlContext& context, const std::filesystem::path& out, ProgressBar& progress);

}  // namespace glint::bench
