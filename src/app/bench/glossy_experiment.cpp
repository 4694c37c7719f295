#include "app/bench/glossy_experiment.h"

#include "app/bench/bench_environment.h"
#include "app/bench/bench_summary.h"
#include "app/bench/experiment_render_options.h"
#include "app/bench/paper_matrix.h"
#include "app/bench/reflection_cost.h"
#include "app/frame_loop.h"
#include "app/output_folder.h"
#include "app/render_command.h"
#include "core/atomic_file.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/image.h"
#include "core/interruption.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "core/utc_timestamp.h"
#include "gl/egl_context.h"
#include "metrics/flicker.h"
#include "metrics/image_comparison.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>

namespace glint::bench {
namespace {

namespace fs = std::filesystem;

// PSNR of identical images is infinite; tables show this instead.
constexpr double kIdenticalPsnr = 100.0;

// What one configuration measured at one frame.
struct GlossyPoint {
  ReflectionCost cost;  // the held frame with the least reflection + resolve time
  double ssim = 1.0, psnr = kIdenticalPsnr;
  metrics::Flicker still, walk;
};

double finite_psnr(double psnr) { return std::isfinite(psnr) ? std::min(psnr, kIdenticalPsnr) : kIdenticalPsnr; }

FrameLoopOptions loop_options(const RenderOptions& render) {
  return {render.width, render.height, render.deform == "on", deforms_on_gpu(render)};
}

// A folder name for a scene: a preset's name, a file's stem, characters other than letters, digits,
// '-', '_' and '.' as '_'.
std::string scene_folder_name(const std::string& scene) {
  std::string name = fs::path(scene).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  return name.empty() ? "scene" : name;
}

std::optional<nlohmann::json> read_json(const fs::path& path) {
  std::ifstream file(path);
  if (!file) return std::nullopt;
  try {
    return nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// The converged reference of every frame: read from DIR/references/<scene>/ when reference.json there
// holds these settings and the frame's PNG is whole and of this size, rendered (and kept) otherwise.
struct References {
  std::vector<ImageRgba8> images;  // one per frame
  nlohmann::json entry;            // for summary.json
};

References converged_references(const Scene& rest, const std::string& name, const std::vector<int>& frames,
                                const std::string& backend, const BenchOptions& options,
                                const HeadlessGlContext& context, ProgressBar& progress) {
  RenderOptions render = experiment_render_options(name, backend, options);
  render.reflections = "rt";
  render.glossy = "on";
  render.spp = options.reference_spp;
  render.denoise = "off";
  const fs::path folder = fs::path(options.out) / "references" / scene_folder_name(name);
  fs::create_directories(folder);
  const nlohmann::json settings = {{"scene", name},           {"width", options.width},
                                   {"height", options.height}, {"backend", backend},
                                   {"reflections", "rt"},      {"glossy", "on"},
                                   {"spp", options.reference_spp}, {"denoise", "off"},
                                   {"blur_radius", render.blur_radius}, {"gbuffer", options.gbuffer},
                                   {"shadows", options.shadows}, {"shadow_map_size", options.shadow_map_size}};
  const fs::path settings_path = folder / "reference.json";
  const bool same_settings = read_json(settings_path) == std::optional<nlohmann::json>(settings);
  // Until every frame is rendered with these settings, no reference.json vouches for the folder.
  if (!same_settings) fs::remove(settings_path);

  References references;
  std::optional<Scene> scene;
  std::optional<FrameLoop> loop;
  double render_ms = 0.0;
  std::size_t cached = 0;
  nlohmann::json files = nlohmann::json::array();
  for (const int frame : frames) {
    throw_if_interrupted("bench");
    const fs::path path = folder / fmt::format("frame_{:05d}.png", frame);
    files.push_back(fs::relative(path, options.out).generic_string());
    if (same_settings && fs::exists(path)) {
      try {
        ImageRgba8 image = read_png(path);
        if (image.width == options.width && image.height == options.height) {
          references.images.push_back(std::move(image));
          ++cached;
          progress.tick();
          continue;
        }
      } catch (const Error& error) {
        log_warning("{}; rendering the reference again", error.what());
      }
    }
    if (!loop) {
      scene.emplace(rest);
      loop.emplace(*scene, render_pipeline_settings(render), loop_options(render),
                   pass_timing_for_renderer(context.renderer()));
    }
    render_ms += loop->run(frame).latency_ms;
    ImageRgba8 image = loop->pipeline().read_final();
    write_png(path, image);
    references.images.push_back(std::move(image));
    progress.tick();
  }
  write_file_atomically(settings_path, settings.dump(2) + "\n");
  const std::size_t rendered = frames.size() - cached;
  references.entry = {{"settings", settings},
                      {"files", std::move(files)},
                      {"cached_frames", cached},
                      {"rendered_frames", rendered},
                      {"mean_latency_ms", rendered > 0 ? render_ms / static_cast<double>(rendered) : 0.0}};
  return references;
}

nlohmann::json flicker_json(const metrics::Flicker& flicker) {
  return {{"percent", 100.0 * flicker.ratio},
          {"mean_abs_change", flicker.mean_abs_change},
          {"mean_luma", flicker.mean_luma},
          {"frames", flicker.frames}};
}

std::string markdown_table(const nlohmann::json& scene) {
  std::string text =
      "| configuration | reflections | glossy | filter | reflection ms | SSR | ray list | trace | hit shade | "
      "resolve | GPU total | rays / reflective px | SSIM vs ref | min SSIM | PSNR vs ref (dB) | flicker still % | "
      "flicker walkthrough % |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const nlohmann::json& point : scene["configs"])
    text += fmt::format(
        "| {} | {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.4f} | {:.4f} "
        "| {:.2f} | {:.3f} | {:.3f} |\n",
        point["label"].get<std::string>(), point["reflections"].get<std::string>(),
        point["glossy"].get<bool>() ? "on" : "off", point["denoise"].get<bool>() ? "denoiser" : "blur",
        point["reflection_ms"].get<double>(), point["ssr_ms"].get<double>(), point["ray_list_ms"].get<double>(),
        point["trace_ms"].get<double>(), point["hit_shade_ms"].get<double>(), point["resolve_ms"].get<double>(),
        point["gpu_total_ms"].get<double>(), point["rays_per_reflective_pixel"].get<double>(),
        point["ssim"].get<double>(), point["ssim_min"].get<double>(), point["psnr_db"].get<double>(),
        point["flicker_still_percent"].get<double>(), point["flicker_walkthrough_percent"].get<double>());
  return text;
}

}  // namespace

std::vector<GlossyConfig> glossy_configs() {
  std::vector<GlossyConfig> configs{{"hybrid-mirror", "hybrid", false, false}};
  for (const char* mode : {"ssr", "hybrid", "rt"}) {
    configs.push_back({mode, mode, true, false});
    configs.push_back({std::string(mode) + "+denoise", mode, true, true});
  }
  return configs;
}

std::vector<int> walkthrough_series(int frame, int flicker_frames) {
  std::vector<int> frames;
  for (int f = std::max(0, frame - flicker_frames); f <= frame; ++f) frames.push_back(f);
  return frames;
}

int run_glossy_experiment(const BenchOptions& options) {
  if (options.flicker_frames < 2) fail("--flicker-frames {}: a flicker series needs at least 2 frames", options.flicker_frames);
  const fs::path out = options.out;
  const std::string backend = first_available_backend(options.backends);
  const std::vector<GlossyConfig> configs = glossy_configs();
  std::vector<std::string> scene_names{options.scene};
  if (options.simple_scene != options.scene) scene_names.push_back(options.simple_scene);
  // Rest poses: every loop poses a copy of its own (a deformer takes the pose it is built on as rest).
  std::map<std::string, Scene> scenes;
  std::map<std::string, std::vector<int>> measured_frames;
  for (const std::string& name : scene_names) {
    Scene& scene = scenes.emplace(name, load_scene(name)).first->second;
    std::vector<int> frames;
    for (const int frame : quality_frames(scene.walkthrough.frame_count))
      if (frame < options.frames) frames.push_back(frame);
    if (frames.empty())
      fail("--frames {}: none of the quality frames (1800, 2100, 2300, 4400) of {}'s walkthrough ({} frames) is below it",
           options.frames, name, scene.walkthrough.frame_count);
    measured_frames[name] = std::move(frames);
  }

  const OutputFolder folder(out);
  HeadlessGlContext context;
  std::size_t ticks = 0;
  for (const std::string& name : scene_names) ticks += (configs.size() + 1) * measured_frames.at(name).size();
  ProgressBar progress("bench glossy", ticks);
  const InterruptionScope interruptible;
  const int series = options.flicker_frames;

  CsvWriter csv(out / "glossy.csv",
                {"scene", "frame", "config", "reflections", "glossy", "denoise", "reflection_ms", "ssr_ms", "ray_list_ms",
                 "trace_ms", "hit_shade_ms", "resolve_ms", "gpu_total_ms", "rays", "reflective_pixels", "ssim_luma",
                 "psnr_db", "flicker_still_percent", "flicker_walkthrough_percent", "still_mean_abs_change",
                 "walkthrough_mean_abs_change", "mean_luma"});
  nlohmann::json scene_entries = nlohmann::json::array();
  for (const std::string& name : scene_names) {
    const Scene& rest = scenes.at(name);
    const std::vector<int>& frames = measured_frames.at(name);
    const References references = converged_references(rest, name, frames, backend, options, context, progress);
    nlohmann::json entries = nlohmann::json::array();
    for (const GlossyConfig& config : configs) {
      RenderOptions render = experiment_render_options(name, backend, options);
      render.reflections = config.reflections;
      render.glossy = config.glossy ? "on" : "off";
      render.denoise = config.denoise ? "on" : "off";
      Scene scene = rest;
      FrameLoop loop(scene, render_pipeline_settings(render), loop_options(render),
                     pass_timing_for_renderer(context.renderer()));
      std::vector<GlossyPoint> points;
      for (std::size_t f = 0; f < frames.size(); ++f) {
        GlossyPoint& point = points.emplace_back();
        // Along the walkthrough up to the measured frame: its history, its quality, flicker in motion.
        loop.set_hold_frame(std::nullopt);
        metrics::FlickerMeter walk;
        for (const int frame : walkthrough_series(frames[f], series)) {
          throw_if_interrupted("bench");
          (void)loop.run(frame);
          walk.add(loop.pipeline().read_final());
        }
        const metrics::ImageComparison c =
            metrics::compare_images(loop.pipeline().read_final(), references.images[f], config.label, "reference");
        point.ssim = c.ssim.luma;
        point.psnr = finite_psnr(c.error.psnr);
        point.walk = walk.result();
        // The same frame held still while the frame number (sampling, history) goes on: a warm-up,
        // then the measured series; its cost is that of the least disturbed of those identical frames.
        loop.set_hold_frame(frames[f]);
        int number = frames[f];
        for (int i = 0; i < series; ++i) {
          throw_if_interrupted("bench");
          (void)loop.run(++number);
        }
        metrics::FlickerMeter still;
        std::optional<ReflectionCost> least;
        for (int i = 0; i <= series; ++i) {
          throw_if_interrupted("bench");
          const ReflectionCost cost = reflection_cost(loop.run(++number));
          if (!least || cost.reflection_ms() + cost.resolve_ms < least->reflection_ms() + least->resolve_ms) least = cost;
          still.add(loop.pipeline().read_final());
        }
        point.cost = *least;
        point.still = still.result();
        const ReflectionCost& k = point.cost;
        csv.add_row({name, frames[f], config.label, config.reflections, config.glossy ? "on" : "off",
                     config.denoise ? "on" : "off", k.reflection_ms(), k.ssr_ms, k.ray_list_ms, k.trace_ms,
                     k.hit_shade_ms, k.resolve_ms, k.gpu_total_ms, k.rays, k.reflective, point.ssim, point.psnr,
                     100.0 * point.still.ratio, 100.0 * point.walk.ratio, point.still.mean_abs_change,
                     point.walk.mean_abs_change, point.still.mean_luma});
        progress.tick();
      }
      const auto mean = [&](auto member) {
        double sum = 0.0;
        for (const GlossyPoint& p : points) sum += member(p);
        return sum / static_cast<double>(points.size());
      };
      const double rays = mean([](const GlossyPoint& p) { return p.cost.rays; });
      const double reflective = mean([](const GlossyPoint& p) { return p.cost.reflective; });
      nlohmann::json per_frame = nlohmann::json::array();
      for (std::size_t f = 0; f < frames.size(); ++f)
        per_frame.push_back({{"frame", frames[f]},
                             {"ssim", points[f].ssim},
                             {"psnr_db", points[f].psnr},
                             {"flicker_still", flicker_json(points[f].still)},
                             {"flicker_walkthrough", flicker_json(points[f].walk)}});
      entries.push_back(
          {{"label", config.label},
           {"reflections", config.reflections},
           {"glossy", config.glossy},
           {"denoise", config.denoise},
           {"reflection_ms", mean([](const GlossyPoint& p) { return p.cost.reflection_ms(); })},
           {"ssr_ms", mean([](const GlossyPoint& p) { return p.cost.ssr_ms; })},
           {"ray_list_ms", mean([](const GlossyPoint& p) { return p.cost.ray_list_ms; })},
           {"trace_ms", mean([](const GlossyPoint& p) { return p.cost.trace_ms; })},
           {"hit_shade_ms", mean([](const GlossyPoint& p) { return p.cost.hit_shade_ms; })},
           {"resolve_ms", mean([](const GlossyPoint& p) { return p.cost.resolve_ms; })},
           {"gpu_total_ms", mean([](const GlossyPoint& p) { return p.cost.gpu_total_ms; })},
           {"rays", rays},
           {"rays_per_reflective_pixel", reflective > 0.0 ? rays / reflective : 0.0},
           {"ssim", mean([](const GlossyPoint& p) { return p.ssim; })},
           {"ssim_min", std::min_element(points.begin(), points.end(), [](const auto& a, const auto& b) {
                          return a.ssim < b.ssim;
                        })->ssim},
           {"psnr_db", mean([](const GlossyPoint& p) { return p.psnr; })},
           {"flicker_still_percent", mean([](const GlossyPoint& p) { return 100.0 * p.still.ratio; })},
           {"flicker_walkthrough_percent", mean([](const GlossyPoint& p) { return 100.0 * p.walk.ratio; })},
           {"frames", std::move(per_frame)}});
    }
    scene_entries.push_back(
        {{"scene", name}, {"frames", frames}, {"reference", references.entry}, {"configs", std::move(entries)}});
  }
  csv.commit();
  progress.finish();

  const nlohmann::json summary = {
      {"experiment", "glossy"},
      {"command", options.command_line},
      {"environment", describe_environment(context)},
      {"settings",
       {{"width", options.width}, {"height", options.height}, {"backend", backend},
        {"reference_spp", options.reference_spp}, {"flicker_frames", options.flicker_frames},
        {"gbuffer", options.gbuffer}, {"shadows", options.shadows}, {"shadow_map_size", options.shadow_map_size}}},
      {"scenes", scene_entries}};
  write_summary(out, summary);

  std::string report = fmt::format(
      "# glint bench --experiment glossy\n\n- date: {}\n- command: `{}`\n- renderer: {}\n- backend: {}\n"
      "- resolution: {}x{}; reference: rt, {} samples per pixel, no denoiser (references/<scene>/)\n"
      "- flicker series: {} frames\n\n"
      "Glossy reflections (--glossy on) at 1 sample per pixel with the paper's blur or the denoiser, and mirror "
      "hybrid (--glossy off, the paper's frame). SSIM (luma) and PSNR against the reference at the same frame, "
      "after the {} walkthrough frames before it (the denoiser's history). Reflection ms = SSR + ray list + trace "
      "+ hit shading; resolve = blur or denoiser; GPU total = every timed pass; all from the held frame with the "
      "least reflection + resolve time. Flicker = mean absolute frame-to-frame change of luma / mean luma, in %: "
      "still = the frame held (camera, light and meshes at the measured frame, the frame number advancing) after "
      "{} frames of warm-up; walkthrough = the consecutive frames up to the measured one, real motion included. "
      "Means over the frames; PSNR of identical images shown as {} dB.\n",
      utc_timestamp(), options.command_line, context.renderer(), backend, options.width, options.height,
      options.reference_spp, options.flicker_frames, options.flicker_frames, options.flicker_frames, kIdenticalPsnr);
  for (const nlohmann::json& scene : scene_entries) {
    const nlohmann::json& reference = scene["reference"];
    report += fmt::format("\n## {} (frames {})\n\nReference: {} frame(s) rendered, {} reused from an earlier run.\n\n{}",
                          scene["scene"].get<std::string>(), scene["frames"].dump(),
                          reference["rendered_frames"].get<std::size_t>(), reference["cached_frames"].get<std::size_t>(),
                          markdown_table(scene));
  }
  write_file_atomically(out / "report.md", report);
  for (const nlohmann::json& scene : scene_entries) {
    fmt::print("{}\n", scene["scene"].get<std::string>());
    for (const nlohmann::json& point : scene["configs"])
      fmt::print("  {:<16} {:8.3f} ms + resolve {:7.3f} ms  SSIM {:.4f}  PSNR {:5.1f}  flicker still {:6.3f} %  "
                 "walkthrough {:6.3f} %\n",
                 point["label"].get<std::string>(), point["reflection_ms"].get<double>(),
                 point["resolve_ms"].get<double>(), point["ssim"].get<double>(), point["psnr_db"].get<double>(),
                 point["flicker_still_percent"].get<double>(), point["flicker_walkthrough_percent"].get<double>());
  }
  return 0;
}

}  // namespace glint::bench
