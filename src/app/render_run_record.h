#pragma once
// What `glint render` records about a run: the timings.csv rows (one per frame) and run.json (the
// command line, scene statistics, GL renderer, resolution, options, and per-pass means over the
// frames). Kept apart from the render loop so the loop reads as the frame's steps.
#include "app/render_command.h"
#include "core/csv_writer.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "render/ssr_pass.h"
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace glint {

class RenderRunRecord {
public:
  RenderRunRecord(const RenderOptions& options, const Scene& scene, const HeadlessGlContext& context,
                  PassTimingMethod pass_timing, const std::vector<int>& frames);

  // Column names of timings.csv: frame, <pass>_ms for every pass of render::kFramePassNames,
  // gpu_total_ms, cpu_frame_ms, deform_ms, triangles, reflective_pixels, ssr_failed_pixels.
  static std::vector<std::string> timings_header();

  // The timings.csv row of one frame (and remembers it for the means in run.json). A pass that did
  // not run (ssr with reflections off) and counts that were not made are empty fields.
  std::vector<CsvField> add_frame(int frame, const FrameTimes& times, double cpu_frame_ms, double deform_ms,
                                  const std::optional<render::SsrCounts>& counts);

  // Writes run.json (atomically) with the means over the frames recorded so far, leaving out the
  // first frame when there are more (it pays for shader compilation and first-touch uploads).
  void write(const std::filesystem::path& path, double wall_ms) const;

private:
  nlohmann::json run_;
  std::size_t triangles_ = 0;
  // Per recorded frame: milliseconds by column name (passes, gpu_total, cpu_frame, deform).
  std::vector<std::map<std::string, double>> frame_ms_;
};

}  // namespace glint
