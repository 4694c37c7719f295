#pragma once
// What `glint render` records about a run: the timings.csv rows (one per frame) and run.json (the
// command line, scene statistics, GL renderer, resolution, options, and per-pass means over the
// frames). Kept apart from the render loop so the loop reads as the frame's steps.
#include "app/frame_loop.h"
#include "app/render_command.h"
#include "core/csv_writer.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "render/ray_traced_reflections.h"
#include "render/ssr_pass.h"
#include "rt/ray_tracer.h"
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

  // What one frame measured (FrameLoop::run).
  using Frame = FrameMeasurement;

  // Column names of timings.csv: frame, <pass>_ms for every pass of render::kFramePassNames,
  // gpu_total_ms, cpu_frame_ms, deform_ms, accel_update_ms, trace_ms, triangles, reflective_pixels,
  // ssr_failed_pixels, rays_traced.
  static std::vector<std::string> timings_header();

  // The timings.csv row of one frame (and remembers it for the means in run.json). A pass that did
  // not run (ssr with reflections off) and counts that were not made are empty fields.
  std::vector<CsvField> add_frame(const Frame& frame);

  // The ray tracer's backend, structure, policy and build statistics, for run.json.
  void set_ray_tracer(const render::RayTracingSettings& settings, const rt::RayTracerStats& stats);

  // Writes run.json (atomically) with the means over the frames recorded so far, leaving out the
  // first frame when there are more (it pays for shader compilation and first-touch uploads), and
  // the ray tracer's final statistics when there is one.
  void write(const std::filesystem::path& path, double wall_ms,
             const std::optional<rt::RayTracerStats>& final_tracer_stats = std::nullopt) const;

private:
  nlohmann::json run_;
  std::size_t triangles_ = 0;
  // Per recorded frame: milliseconds by column name (passes, gpu_total, cpu_frame, deform).
  std::vector<std::map<std::string, double>> frame_ms_;
};

}  // namespace glint
