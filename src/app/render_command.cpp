#include "app/render_command.h"

#include "app/frame_selection.h"
#include "app/output_folder.h"
#include "app/render_run_record.h"
#include "app/video_writer.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "render/frame_pipeline.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"
#include "scene/sine_deformer.h"

#include <epoxy/gl.h>

#include <chrono>
#include <optional>

namespace glint {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

render::FramePipelineSettings pipeline_settings(const RenderOptions& options) {
  render::FramePipelineSettings settings;
  settings.reflections = render::parse_reflection_mode(options.reflections);
  settings.raster.shadow_map_size = options.shadow_map_size;
  settings.ssr.max_steps = options.ssr_max_steps;
  settings.ssr.thickness = options.ssr_thickness;
  settings.ssr.confidence_threshold = options.ssr_confidence;
  settings.resolve.blur_radius = options.blur_radius;
  settings.resolve.exposure = options.exposure;
  settings.resolve.tone_map = render::tone_map_from_name(options.tone_map);
  settings.validate();
  return settings;
}

// Moves the deformable meshes to `frame` and copies their new vertices to the GPU; returns the time.
double deform(SceneDeformers* deformers, Scene& scene, render::FramePipeline& pipeline, int frame) {
  if (deformers == nullptr) return 0.0;
  const auto start = Clock::now();
  for (const std::uint32_t mesh : deformers->apply(scene, frame))
    pipeline.raster().gpu_scene().update_mesh_vertices(mesh, scene.meshes[mesh].positions, scene.meshes[mesh].normals);
  return milliseconds_since(start);
}

}  // namespace

void add_render_command(CLI::App& app, RenderOptions& options) {
  CLI::App* command = app.add_subcommand(
      "render", "Render frames of a scene's walkthrough headless: PNG frames, timings.csv, run.json");
  command->add_option("scene", options.scene, "Preset (atrium, atrium-simple, sponza) or scene file")
      ->capture_default_str();
  command->add_option("--reflections", options.reflections, "Reflections: off (direct light only) or ssr")
      ->check(CLI::IsMember({"off", "ssr"}))
      ->capture_default_str();
  command->add_option("--width", options.width, "Image width in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  command->add_option("--height", options.height, "Image height in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  command->add_option("--frames", options.frames,
                      "Frames to render: N, A:B (inclusive), A:B:step, or a comma list such as 1800,2100,2300,4400; "
                      "default: the whole walkthrough");
  command->add_option("--out", options.out, "Output folder (created if missing)")->capture_default_str();
  command->add_flag("--debug-views", options.debug_views,
                    "Also write albedo, normals, positions, depth, shadow mask, SSR reflection and failure mask per frame");
  command->add_flag("--video", options.video, "Also encode DIR/walkthrough.mp4 with ffmpeg (must be on PATH)");
  command->add_flag("--timings-only", options.timings_only,
                    "Write no images, only timings.csv and run.json: frames follow each other without the "
                    "PNG encoding in between, so the GPU stays busy (for measurements)")
      ->excludes("--video")
      ->excludes("--debug-views");
  command->add_option("--deform", options.deform, "Animate the deformable meshes: on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command->add_option("--blur-radius", options.blur_radius, "Reflection blur radius in pixels (0 = off)")
      ->check(CLI::Range(0, 32))
      ->capture_default_str();
  command->add_option("--exposure", options.exposure, "Exposure applied before the tone map")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--tone-map", options.tone_map, "Tone map: aces, reinhard or none")
      ->check(CLI::IsMember({"aces", "reinhard", "none"}))
      ->capture_default_str();
  command->add_option("--shadow-map-size", options.shadow_map_size, "Shadow cube map face size in texels")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  command->add_option("--ssr-max-steps", options.ssr_max_steps, "Most screen-space march steps per pixel")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  command->add_option("--ssr-thickness", options.ssr_thickness, "Assumed surface thickness for SSR hits (world units)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--ssr-confidence", options.ssr_confidence,
                      "Lowest confidence of a trusted SSR hit; below it the pixel fails (0..1)")
      ->check(CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
}

int run_render_command(const RenderOptions& options) {
  const render::FramePipelineSettings settings = pipeline_settings(options);
  const FrameSelection selection = options.frames.empty() ? FrameSelection::all() : FrameSelection::parse(options.frames);

  Scene scene = load_scene(options.scene);
  const WalkthroughAnimation animation(scene);
  const std::vector<int> frames = selection.resolve(animation.frame_count());
  std::optional<SceneDeformers> deformers;
  if (options.deform == "on" && !scene.deformable_meshes().empty()) deformers.emplace(scene);

  const OutputFolder out(options.out);
  HeadlessGlContext context;  // logs its renderer with --verbose
  render::FramePipeline pipeline(scene, options.width, options.height, settings);
  GpuTimer timer(pass_timing_for_renderer(context.renderer()));

  RenderRunRecord record(options, scene, context, timer.method(), frames);
  CsvWriter timings(out.path() / "timings.csv", RenderRunRecord::timings_header());
  std::optional<FfmpegVideoWriter> video;
  if (options.video)
    video.emplace(out.path() / "walkthrough.mp4", options.width, options.height, scene.walkthrough.frames_per_second);

  ProgressBar progress("render", frames.size());
  const auto run_start = Clock::now();
  for (const int frame : frames) {
    const auto frame_start = Clock::now();
    const double deform_ms = deform(deformers ? &*deformers : nullptr, scene, pipeline, frame);
    timer.begin_frame();
    pipeline.render(animation.at(frame), &timer);
    timer.end_frame();
    glFinish();  // the CPU frame time includes the GPU finishing the frame
    const double cpu_frame_ms = milliseconds_since(frame_start);

    if (!options.timings_only) {
      const ImageRgba8 image = pipeline.read_final();
      write_png(out.frame_path(frame), image);
      if (video) video->add_frame(image);
    }
    if (options.debug_views)
      for (const render::DebugView& view : pipeline.read_debug_views()) write_png(out.debug_view_path(frame, view.name), view.image);

    timer.wait_for_all();
    for (const FrameTimes& times : timer.take_completed())
      timings.add_row(record.add_frame(frame, times, cpu_frame_ms, deform_ms, pipeline.read_counts()));
    progress.tick();
  }
  progress.finish();
  if (video) video->finish();
  timings.commit();
  record.write(out.path() / "run.json", milliseconds_since(run_start));
  log_info("wrote {} frames to {}", frames.size(), out.path().string());
  return 0;
}

}  // namespace glint
