#include "app/bench/cell_run.h"

#include "app/frame_loop.h"
#include "app/output_folder.h"
#include "app/render_command.h"
#include "app/render_run_record.h"
#include "core/atomic_file.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/image.h"
#include "core/interruption.h"
#include "core/untrusted_text.h"
#include "metrics/image_comparison.h"
#include "rt/instance_subset_tracer.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <map>
#include <optional>

namespace glint::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The `glint render` options that run `cell` in `reflections` mode, so a cell is exactly what the
// same render command would measure.
RenderOptions render_options(const Cell& cell, const std::string& reflections, const CellRunSettings& settings) {
  RenderOptions options;
  options.scene = cell.scene;
  options.reflections = reflections;
  if (!cell.structure.backend.empty()) options.backend = cell.structure.backend;
  // Backends that build their own structures take render's default (the flag does not apply).
  options.accel = cell.structure.accel.empty() ? RenderOptions{}.accel : cell.structure.accel;
  options.update = cell.update.empty() ? "rebuild" : cell.update;
  options.width = settings.width;
  options.height = settings.height;
  options.timings_only = true;
  options.deform = cell.deform ? "on" : "off";
  // Fig. 10's tracer sees a subset of the scene, renumbered on the host (rt::InstanceSubsetTracer),
  // which a GPU deformer cannot write into.
  if (cell.trace_deformable_only) options.deform_on = "cpu";
  options.shadow_map_size = settings.shadow_map_size;
  options.gbuffer = settings.gbuffer;
  options.shadows = settings.shadows;
  // The paper's reflections: mirrors, one sample, its Gaussian blur (docs/glossy.md).
  options.glossy = "off";
  options.spp = 1;
  options.denoise = "off";
  options.command_line = settings.command_line;
  return options;
}

render::FramePipelineSettings pipeline_settings(const Cell& cell, const RenderOptions& options, const Scene& scene) {
  render::FramePipelineSettings pipeline = render_pipeline_settings(options);
  if (cell.trace_deformable_only) {
    pipeline.ray_tracing.traced_instances = rt::deformable_instances(scene);
    if (pipeline.ray_tracing.traced_instances.empty()) fail("{}: the scene has no deformable meshes to trace", cell.scene);
  }
  return pipeline;
}

nlohmann::json tracer_json(const rt::RayTracer* tracer) {
  if (tracer == nullptr) return nullptr;
  const rt::RayTracerStats stats = tracer->stats();
  nlohmann::json json = {{"backend", stats.backend},
                         {"build_ms", stats.build_ms},
                         {"memory_bytes", stats.memory_bytes},
                         {"rebuilds", stats.rebuilds},
                         {"refits", stats.refits}};
  if (stats.blas_sah_drift) json["final_blas_sah_drift"] = *stats.blas_sah_drift;
  return json;
}

nlohmann::json scene_json(const Scene& scene) {
  return {{"name", untrusted_text(scene.name)},
          {"vertices", scene.vertex_count()},
          {"triangles", scene.triangle_count()},
          {"deformable_meshes", scene.deformable_meshes().size()}};
}

FrameLoop make_loop(const Cell& cell, Scene& scene, const RenderOptions& options, const HeadlessGlContext& context) {
  return FrameLoop(scene, pipeline_settings(cell, options, scene),
                   {options.width, options.height, cell.deform, deforms_on_gpu(options)},
                   pass_timing_for_renderer(context.renderer()));
}

void run_frame_times(const Cell& cell, Scene& scene, const std::vector<int>& frames, const CellRunSettings& settings,
                     const HeadlessGlContext& context, const std::filesystem::path& out, ProgressBar& progress) {
  const auto start = Clock::now();
  const RenderOptions options = render_options(cell, cell.reflections, settings);
  FrameLoop loop = make_loop(cell, scene, options, context);
  RenderRunRecord record(options, scene, context, loop.pass_timing(), frames);
  CsvWriter csv(cell_csv_path(out, cell), RenderRunRecord::timings_header());
  // Pipelined as `glint render --timings-only`: frames come back complete and in order, a few frames
  // late. The warm-up frames (shader compilation, first-touch uploads and caches are paid before
  // measuring) go through the same pipeline, so the first measured frame already finds it full;
  // they come back first and are left out.
  int warmup_left = settings.warmup_frames;
  const auto keep = [&](const FrameMeasurement& measured) {
    if (warmup_left > 0) --warmup_left;
    else csv.add_row(record.add_frame(measured));
    progress.tick();
  };
  for (int i = 0; i < settings.warmup_frames; ++i)
    for (const FrameMeasurement& measured : loop.submit(frames.front())) keep(measured);
  for (const int frame : frames) {
    throw_if_interrupted("bench");
    for (const FrameMeasurement& measured : loop.submit(frame)) keep(measured);
  }
  for (const FrameMeasurement& measured : loop.drain()) keep(measured);
  const nlohmann::json side = {{"id", cell.id},
                               {"scene", scene_json(scene)},
                               {"ray_tracer", tracer_json(loop.pipeline().ray_tracer())},
                               {"warmup_frames", settings.warmup_frames},
                               {"wall_seconds", seconds_since(start)}};
  write_file_atomically(cell_json_path(out, cell), side.dump(2) + "\n");
  csv.commit();
}

void run_quality(const Cell& cell, Scene& scene, const std::vector<int>& frames, const CellRunSettings& settings,
                 const HeadlessGlContext& context, const std::filesystem::path& out, ProgressBar& progress) {
  const auto start = Clock::now();
  const OutputFolder images(cell_image_folder(out, cell));
  // Every mode renders the same frames of the same (deforming) scene; rt is the reference.
  std::map<std::string, std::vector<ImageRgba8>> rendered;
  nlohmann::json tracers = nlohmann::json::object();
  for (const char* mode : {"rt", "ssr", "hybrid"}) {
    const RenderOptions options = render_options(cell, mode, settings);
    FrameLoop loop = make_loop(cell, scene, options, context);
    for (const int frame : frames) {
      throw_if_interrupted("bench");
      (void)loop.run(frame);
      ImageRgba8 image = loop.pipeline().read_final();
      write_png(images.path() / fmt::format("frame_{:05d}_{}.png", frame, mode), image);
      rendered[mode].push_back(std::move(image));
      progress.tick();
    }
    tracers[mode] = tracer_json(loop.pipeline().ray_tracer());
  }
  CsvWriter csv(cell_csv_path(out, cell), cell_csv_header(CellKind::quality));
  for (std::size_t i = 0; i < frames.size(); ++i) {
    for (const char* mode : kComparedModes) {
      const metrics::ImageComparison c = metrics::compare_images(rendered[mode][i], rendered["rt"][i], mode, "rt");
      csv.add_row({frames[i], mode, c.buckets.channel_percent[0], c.buckets.channel_percent[1],
                   c.buckets.channel_percent[2], c.buckets.mean_percent, c.ssim.luma, c.error.rmse, c.error.psnr});
    }
  }
  const nlohmann::json side = {{"id", cell.id},
                               {"scene", scene_json(scene)},
                               {"ray_tracer", tracers},
                               {"wall_seconds", seconds_since(start)}};
  write_file_atomically(cell_json_path(out, cell), side.dump(2) + "\n");
  csv.commit();
}

}  // namespace

std::filesystem::path cell_csv_path(const std::filesystem::path& out, const Cell& cell) {
  return out / "cells" / (cell.id + ".csv");
}
std::filesystem::path cell_json_path(const std::filesystem::path& out, const Cell& cell) {
  return out / "cells" / (cell.id + ".json");
}
std::filesystem::path cell_image_folder(const std::filesystem::path& out, const Cell& cell) {
  return out / "cells" / cell.id;
}

std::vector<std::string> cell_csv_header(CellKind kind) {
  if (kind == CellKind::frame_times) return RenderRunRecord::timings_header();
  return {"frame",        "mode", "buckets_r_percent", "buckets_g_percent", "buckets_b_percent", "buckets_mean_percent",
          "ssim_luma", "rmse", "psnr_db"};
}

std::size_t cell_ticks(const Cell& cell, std::size_t frames, const CellRunSettings& settings) {
  if (cell.kind == CellKind::quality) return 3 * frames;
  return frames + static_cast<std::size_t>(settings.warmup_frames);
}

void run_cell(const Cell& cell, Scene scene, const std::vector<int>& frames, const CellRunSettings& settings,
              const HeadlessGlContext& context, const std::filesystem::path& out, ProgressBar& progress) {
  if (frames.empty()) fail("bench cell {}: no frames to render", cell.id);
  std::filesystem::create_directories(out / "cells");
  if (cell.kind == CellKind::quality) run_quality(cell, scene, frames, settings, context, out, progress);
  else run_frame_times(cell, scene, frames, settings, context, out, progress);
}

}  // namespace glint::bench
