#pragma once
// What `glint render` records about a run: the timings.csv rows (one per frame) and run.json (the
// command line, scene statistics, GL renderer, resolution, options, and per-pass means over the
// frames). Kept apart from the render loop so the loop reads as the frame's steps.
#include "app/frame_loop.h"
#include "app/render_command.h"
#include "core/csv_writer.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "render/raster_pipeline.h"
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

// run.json's "primary_visibility": null with the raster G-buffer (no ids); else {"method": raster |
// compute | rt}, and with --primary auto also "chosen_by" and, where they were timed (not on a
// software renderer), both methods' "raster_ms" and "compute_ms" ({"method": "auto"} before any frame).
nlohmann::json primary_visibility_record(const render::RasterPipeline& raster);

class RenderRunRecord {
public:
  RenderRunRecord(const RenderOptions& options, const Scene& scene, const HeadlessGlContext& context,
                  PassTimingMethod pass_timing, const std::vector<int>& frames);

  // What one frame measured (FrameLoop::submit/drain).
  using Frame = FrameMeasurement;

  // Column names of timings.csv: frame, <pass>_ms for every pass of render::kFramePassNames,
  // gpu_total_ms, frame_ms (steady state: previous frame's completion to this one's),
  // frame_latency_ms (this frame's CPU start to its GPU end), deform_ms, accel_update_ms, trace_ms, triangles, reflective_pixels,
  // ssr_failed_pixels, rays_traced, resident_mb, gpu_memory_used_mb, auto's columns, hit_shadow_trace_ms.
  static std::vector<std::string> timings_header();

  // The timings.csv row of one frame (and remembers it for the means in run.json). A pass that did
  // not run (ssr with reflections off) and counts that were not made are empty fields.
  std::vector<CsvField> add_frame(const Frame& frame);

  // A frame measured by another process (a rank of `mpirun glint render`, app/mpi/render_share.h),
  // given as the timings.csv row its add_frame made: remembered for the means as add_frame does.
  void add_row(const std::vector<std::string>& row);

  // A top-level entry of run.json (a run shared over MPI ranks records them under "distribution").
  void add_entry(const std::string& key, const nlohmann::json& value) { run_[key] = value; }

  // How the visibility G-buffer's ids were made, as primary_visibility_record says (run.json
  // "primary_visibility"); called after the frames, since --primary auto chooses on the first.
  void set_primary_visibility(const render::RasterPipeline& raster) {
    run_["primary_visibility"] = primary_visibility_record(raster);
  }

  // The ray tracer's backend, structure, policy and build statistics, for run.json.
  void set_ray_tracer(const render::RayTracingSettings& settings, const rt::RayTracerStats& stats);

  // Records in run.json that the run was stopped by `signal` ("SIGINT") before all its frames.
  void mark_interrupted(const char* signal);

  // Writes run.json (atomically) with the means over the frames recorded so far, leaving out the
  // first frame when there are more (it pays for shader compilation and first-touch uploads), and
  // the ray tracer's final statistics when there is one.
  void write(const std::filesystem::path& path, double wall_ms,
             const std::optional<rt::RayTracerStats>& final_tracer_stats = std::nullopt) const;

private:
  nlohmann::json run_;
  std::size_t triangles_ = 0;
  // Running sums, so a run of any length holds the same few numbers (docs/reliability.md's soak runs):
  // the first frame's values by column name (passes, gpu_total, frame, frame_latency, deform, ...) and the sums
  // over the later frames, which the means use.
  std::map<std::string, double> first_frame_;
  std::map<std::string, double> later_sums_;
  std::size_t frames_recorded_ = 0;
  // Resident and GPU memory after the first and the last frame, and their peaks (bytes).
  struct MemorySamples {
    std::optional<std::uint64_t> first, last, peak;
    void add(std::optional<std::uint64_t> bytes);
  };
  MemorySamples resident_, gpu_memory_;
};

}  // namespace glint
