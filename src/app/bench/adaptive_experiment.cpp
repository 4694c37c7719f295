#include "app/bench/adaptive_experiment.h"

#include "app/bench/backend_availability.h"
#include "app/bench/bench_environment.h"
#include "app/bench/bench_summary.h"
#include "app/bench/experiment_render_options.h"
#include "app/bench/paper_matrix.h"
#include "app/bench/plot_script.h"
#include "app/bench/reflection_cost.h"
#include "app/frame_loop.h"
#include "app/output_folder.h"
#include "app/render_command.h"
#include "backends/registry.h"
#include "core/atomic_file.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/image.h"
#include "core/interruption.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "core/stopwatch.h"
#include "core/utc_timestamp.h"
#include "gl/egl_context.h"
#include "metrics/image_comparison.h"
#include "render/ray_origin_offset.h"
#include "render/scene_reflection_fade.h"
#include "render/screen_space_reach.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace glint::bench {
namespace {

namespace fs = std::filesystem;

// Renders of each measured frame; the one with the least reflection time is kept.
constexpr int kMeasuredRepeats = 3;

// PSNR of identical images is infinite; tables and charts show this instead.
constexpr double kIdenticalPsnr = 100.0;

// What one configuration measured at one frame.
struct AdaptivePoint {
  double ssr_ms = 0.0, ray_list_ms = 0.0, trace_ms = 0.0, hit_shade_ms = 0.0, classify_ms = 0.0;
  double rays = 0.0, reflective = 0.0;
  double ssim = 1.0, psnr = kIdenticalPsnr;
  double reflection_ms() const { return ssr_ms + ray_list_ms + trace_ms + hit_shade_ms + classify_ms; }
};

RenderOptions render_options(const std::string& scene, const AdaptiveConfig& config, const std::string& backend,
                             const BenchOptions& options) {
  RenderOptions render = experiment_render_options(scene, backend, options);
  render.reflections = config.reflections;
  render.ray_budget = config.ray_budget;
  render.deform = "off";  // Table I's static frames: every configuration sees the same geometry
  return render;
}

AdaptivePoint measured_point(const FrameMeasurement& frame) {
  const ReflectionCost cost = reflection_cost(frame);
  AdaptivePoint point;
  point.ssr_ms = cost.ssr_ms;
  point.ray_list_ms = cost.ray_list_ms;
  point.trace_ms = cost.trace_ms;
  point.hit_shade_ms = cost.hit_shade_ms;
  point.classify_ms = cost.classify_ms;
  point.rays = cost.rays;
  point.reflective = cost.reflective;
  return point;
}

double finite_psnr(double psnr) { return std::isfinite(psnr) ? std::min(psnr, kIdenticalPsnr) : kIdenticalPsnr; }

// Screen-space reach (render/screen_space_reach.h) is traced on the host whatever the bench's
// backend: embree where this binary has it, else glint's cpu backend.
std::string reach_backend() { return backend_unavailable_reason("embree") ? "cpu" : "embree"; }

// The reach of the frame the loop rendered last, from its G-buffer (mirror rays, whatever the
// configuration's sampling), untimed. Counts only: the per-pixel classes are dropped.
render::ScreenSpaceReach measure_reach(FrameLoop& loop, const Scene& scene, const rt::RayTracer& tracer) {
  const render::RasterPipeline& raster = loop.pipeline().raster();
  const ImageRgbaF position = raster.read_rgbaf(render::RasterOutput::WorldPosition);
  const ImageRgbaF normal = raster.read_rgbaf(render::RasterOutput::WorldNormalRoughness);
  const ImageRgbaF albedo = raster.read_rgbaf(render::RasterOutput::AlbedoReflectivity);
  const float offset =
      render::ray_origin_offset(loop.pipeline().settings().ray_tracing.origin_offset_fraction, scene.world_bounds());
  const float fade_end = render::with_scene_fade(loop.pipeline().settings().resolve, scene).fade_end;
  render::ScreenSpaceReach reach = render::measure_screen_space_reach(scene, tracer, {position, normal, albedo, nullptr},
                                                                      raster.frame_constants(), offset, fade_end);
  reach.classes = {};
  return reach;
}

// The reach columns of adaptive.csv and the report, in percent of the reflective pixels.
struct ReachPercents {
  double on_screen = 0.0, off_screen = 0.0, occluded = 0.0, miss = 0.0, miss_leaving_view = 0.0, must_trace = 0.0;
  double must_trace_within_fade = 0.0;
};

ReachPercents reach_percents(const render::ScreenSpaceReach& r) {
  return {r.percent(r.on_screen), r.percent(r.off_screen),        r.percent(r.occluded),
          r.percent(r.miss),      r.percent(r.miss_leaving_view), r.percent(r.must_trace()),
          r.percent(r.must_trace_within_fade)};
}

nlohmann::json reach_json(int frame, const render::ScreenSpaceReach& r) {
  const ReachPercents p = reach_percents(r);
  return {{"frame", frame},
          {"reflective_pixels", r.reflective},
          {"on_screen_percent", p.on_screen},
          {"off_screen_percent", p.off_screen},
          {"occluded_percent", p.occluded},
          {"miss_percent", p.miss},
          {"miss_leaving_view_percent", p.miss_leaving_view},
          {"must_trace_percent", p.must_trace},
          {"must_trace_within_fade_percent", p.must_trace_within_fade}};
}

std::string reach_table(const nlohmann::json& scene) {
  std::string text = "| frame | reflective px | on screen % | off screen % | occluded % | miss % (leaving the view) | "
                     "must trace % (off screen + occluded) | of it nearer than the fade end % |\n"
                     "|---|---|---|---|---|---|---|---|\n";
  for (const nlohmann::json& r : scene["screen_space_reach"]["frames"])
    text += fmt::format("| {} | {} | {:.1f} | {:.1f} | {:.1f} | {:.1f} ({:.1f}) | {:.1f} | {:.1f} |\n", r["frame"].get<int>(),
                        r["reflective_pixels"].get<std::size_t>(), r["on_screen_percent"].get<double>(),
                        r["off_screen_percent"].get<double>(), r["occluded_percent"].get<double>(),
                        r["miss_percent"].get<double>(), r["miss_leaving_view_percent"].get<double>(),
                        r["must_trace_percent"].get<double>(), r["must_trace_within_fade_percent"].get<double>());
  return text;
}

std::string markdown_table(const nlohmann::json& scene) {
  std::string text = "| configuration | reflection ms | SSR | ray list | trace | hit shade | classify | rays / "
                     "reflective px | SSIM vs rt | PSNR vs rt (dB) | Pareto |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const nlohmann::json& point : scene["configs"])
    text += fmt::format("| {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.4f} | {:.1f} | {} |\n",
                        point["label"].get<std::string>(), point["reflection_ms"].get<double>(),
                        point["ssr_ms"].get<double>(), point["ray_list_ms"].get<double>(),
                        point["trace_ms"].get<double>(), point["hit_shade_ms"].get<double>(),
                        point["classify_ms"].get<double>(), point["rays_per_reflective_pixel"].get<double>(),
                        point["ssim"].get<double>(), point["psnr_db"].get<double>(),
                        point["pareto"].get<bool>() ? "yes" : "");
  return text;
}

}  // namespace

std::vector<AdaptiveConfig> adaptive_configs(int width, int height) {
  std::vector<AdaptiveConfig> configs{{"rt", "rt", -1}, {"ssr", "ssr", -1}, {"hybrid", "hybrid", -1}, {"auto", "auto", -1}};
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  for (const double fraction : kAdaptiveBudgetFractions)
    configs.push_back({fmt::format("auto-{:g}%", fraction * 100.0), "auto",
                       static_cast<long long>(std::llround(fraction * pixels))});
  return configs;
}

std::vector<bool> pareto_front(const std::vector<double>& cost, const std::vector<double>& quality) {
  std::vector<bool> front(cost.size(), true);
  for (std::size_t i = 0; i < cost.size(); ++i)
    for (std::size_t j = 0; j < cost.size() && front[i]; ++j)
      if (j != i && cost[j] <= cost[i] && quality[j] >= quality[i] && (cost[j] < cost[i] || quality[j] > quality[i]))
        front[i] = false;
  return front;
}

int run_adaptive_experiment(const BenchOptions& options) {
  const fs::path out = options.out;
  const std::string backend = first_available_backend(options.backends);
  const std::vector<AdaptiveConfig> configs = adaptive_configs(options.width, options.height);
  std::vector<std::string> scene_names{options.scene};
  if (options.simple_scene != options.scene) scene_names.push_back(options.simple_scene);
  std::map<std::string, Scene> scenes;
  for (const std::string& name : scene_names) scenes.emplace(name, load_scene(name));

  const OutputFolder folder(out);
  HeadlessGlContext context;
  std::size_t ticks = 0;
  for (const std::string& name : scene_names)
    ticks += configs.size() * quality_frames(scenes.at(name).walkthrough.frame_count).size();
  ProgressBar progress("bench adaptive", ticks);
  const InterruptionScope interruptible;

  CsvWriter csv(out / "adaptive.csv", {"scene", "frame", "config", "reflections", "ray_budget", "reflection_ms",
                                       "ssr_ms", "ray_list_ms", "trace_ms", "hit_shade_ms", "classify_ms", "rays",
                                       "reflective_pixels", "rays_per_reflective_pixel", "ssim_luma", "psnr_db",
                                       "reach_on_screen_percent", "reach_off_screen_percent", "reach_occluded_percent",
                                       "reach_miss_percent", "reach_miss_leaving_view_percent",
                                       "reach_must_trace_percent", "reach_must_trace_within_fade_percent"});
  const std::string reach_tracer_name = reach_backend();
  nlohmann::json scene_entries = nlohmann::json::array();
  for (const std::string& name : scene_names) {
    Scene& scene = scenes.at(name);
    const std::vector<int> frames = quality_frames(scene.walkthrough.frame_count);
    std::map<std::string, std::vector<AdaptivePoint>> points;
    std::vector<ImageRgba8> reference;
    // Screen-space reach: once per frame, from the rt configuration's G-buffer, on the host.
    const std::unique_ptr<rt::RayTracer> reach_tracer = backends::make_ray_tracer(reach_tracer_name);
    reach_tracer->build(scene, {});
    std::vector<render::ScreenSpaceReach> reach;
    double reach_ms = 0.0;
    for (const AdaptiveConfig& config : configs) {
      const RenderOptions render = render_options(name, config, backend, options);
      FrameLoop loop(scene, render_pipeline_settings(render), {render.width, render.height, false},
                     pass_timing_for_renderer(context.renderer()));
      for (std::size_t f = 0; f < frames.size(); ++f) {
        throw_if_interrupted("bench");
        // The walkthrough's frames just before: auto's history, and every pass warm.
        for (int before = std::min(options.warmup, frames[f]); before > 0; --before) (void)loop.run(frames[f] - before);
        // The least disturbed of a few renders of the frame (a shared machine's other work only adds time).
        AdaptivePoint point = measured_point(loop.run(frames[f]));
        ImageRgba8 image = loop.pipeline().read_final();
        for (int repeat = 1; repeat < kMeasuredRepeats; ++repeat) {
          const AdaptivePoint again = measured_point(loop.run(frames[f]));
          if (again.reflection_ms() >= point.reflection_ms()) continue;
          point = again;
          image = loop.pipeline().read_final();
        }
        if (config.label == "rt") {
          reference.push_back(std::move(image));
          const Stopwatch watch;
          reach.push_back(measure_reach(loop, scene, *reach_tracer));
          reach_ms += watch.elapsed_ms();
        } else {
          const metrics::ImageComparison c = metrics::compare_images(image, reference.at(f), config.label, "rt");
          point.ssim = c.ssim.luma;
          point.psnr = finite_psnr(c.error.psnr);
        }
        const ReachPercents reach_p = reach_percents(reach.at(f));
        csv.add_row({name, frames[f], config.label, config.reflections,
                     config.ray_budget >= 0 ? CsvField(config.ray_budget) : CsvField(""), point.reflection_ms(),
                     point.ssr_ms, point.ray_list_ms, point.trace_ms, point.hit_shade_ms, point.classify_ms,
                     point.rays, point.reflective, point.reflective > 0 ? point.rays / point.reflective : 0.0,
                     point.ssim, point.psnr, reach_p.on_screen, reach_p.off_screen, reach_p.occluded, reach_p.miss,
                     reach_p.miss_leaving_view, reach_p.must_trace, reach_p.must_trace_within_fade});
        points[config.label].push_back(point);
        progress.tick();
      }
    }
    // Means over the frames, and the Pareto front of (reflection ms, SSIM).
    nlohmann::json entries = nlohmann::json::array();
    std::vector<double> cost, quality;
    for (const AdaptiveConfig& config : configs) {
      const std::vector<AdaptivePoint>& list = points.at(config.label);
      const auto mean = [&](auto member) {
        double sum = 0.0;
        for (const AdaptivePoint& p : list) sum += member(p);
        return list.empty() ? 0.0 : sum / static_cast<double>(list.size());
      };
      const double rays = mean([](const AdaptivePoint& p) { return p.rays; });
      const double reflective = mean([](const AdaptivePoint& p) { return p.reflective; });
      nlohmann::json entry = {{"label", config.label},
                              {"reflections", config.reflections},
                              {"ray_budget", config.ray_budget >= 0 ? nlohmann::json(config.ray_budget) : nullptr},
                              {"reflection_ms", mean([](const AdaptivePoint& p) { return p.reflection_ms(); })},
                              {"ssr_ms", mean([](const AdaptivePoint& p) { return p.ssr_ms; })},
                              {"ray_list_ms", mean([](const AdaptivePoint& p) { return p.ray_list_ms; })},
                              {"trace_ms", mean([](const AdaptivePoint& p) { return p.trace_ms; })},
                              {"hit_shade_ms", mean([](const AdaptivePoint& p) { return p.hit_shade_ms; })},
                              {"classify_ms", mean([](const AdaptivePoint& p) { return p.classify_ms; })},
                              {"rays", rays},
                              {"rays_per_reflective_pixel", reflective > 0.0 ? rays / reflective : 0.0},
                              {"ssim", mean([](const AdaptivePoint& p) { return p.ssim; })},
                              {"ssim_min", std::min_element(list.begin(), list.end(), [](const auto& a, const auto& b) {
                                             return a.ssim < b.ssim;
                                           })->ssim},
                              {"psnr_db", mean([](const AdaptivePoint& p) { return p.psnr; })}};
      cost.push_back(entry["reflection_ms"].get<double>());
      quality.push_back(entry["ssim"].get<double>());
      entries.push_back(std::move(entry));
    }
    const std::vector<bool> front = pareto_front(cost, quality);
    for (std::size_t i = 0; i < entries.size(); ++i) entries[i]["pareto"] = static_cast<bool>(front[i]);
    nlohmann::json reach_frames = nlohmann::json::array();
    for (std::size_t f = 0; f < frames.size(); ++f) reach_frames.push_back(reach_json(frames[f], reach.at(f)));
    render::ScreenSpaceReach total;  // all frames' pixels together
    for (const render::ScreenSpaceReach& r : reach) {
      total.reflective += r.reflective;
      total.on_screen += r.on_screen;
      total.off_screen += r.off_screen;
      total.occluded += r.occluded;
      total.miss += r.miss;
      total.miss_leaving_view += r.miss_leaving_view;
      total.must_trace_within_fade += r.must_trace_within_fade;
    }
    nlohmann::json all = reach_json(0, total);
    all.erase("frame");
    scene_entries.push_back({{"scene", name},
                             {"frames", frames},
                             {"configs", std::move(entries)},
                             {"screen_space_reach",
                              {{"backend", reach_tracer_name}, {"ms", reach_ms}, {"frames", std::move(reach_frames)},
                               {"all_frames", std::move(all)}}}});
  }
  csv.commit();
  progress.finish();

  const nlohmann::json summary = {
      {"experiment", "adaptive"},
      {"command", options.command_line},
      {"environment", describe_environment(context)},
      {"settings",
       {{"width", options.width}, {"height", options.height}, {"warmup_frames", options.warmup},
        {"backend", backend}, {"gbuffer", options.gbuffer}, {"shadows", options.shadows},
        {"shadow_map_size", options.shadow_map_size}, {"reach_backend", reach_tracer_name}}},
      {"scenes", scene_entries}};
  write_summary(out, summary);
  std::string chart_note = options.no_plot ? fmt::format("charts not made (--no-plot); run: python3 {} {}",
                                                         (out / "plot_bench.py").string(), out.string())
                                           : plot_bench_charts(out);
  if (options.no_plot) write_file_atomically(out / "plot_bench.py", kPlotBenchScript);
  if (!chart_note.empty()) log_warning("{}", chart_note);

  std::string report = fmt::format(
      "# glint bench --experiment adaptive\n\n- date: {}\n- command: `{}`\n- renderer: {}\n- backend: {}\n"
      "- resolution: {}x{}, {} walkthrough frame(s) before each measured frame, which is rendered {} times "
      "(the render with the least reflection time is kept)\n\n"
      "Quality (SSIM on luma, PSNR) against rt at the same frame, and the reflection cost: SSR + ray list + "
      "trace + hit shading (+ auto's tile classification), means over the frames. auto-N% is auto with "
      "--ray-budget N% of the image's pixels. Pareto: no other configuration is at most as dear and at least "
      "as close to rt (SSIM). rt against itself is shown as SSIM 1, PSNR {} dB.\n\n"
      "Screen-space reach (docs/hybrid.md): each reflective pixel's exact mirror ray, traced on the host with the "
      "{} backend (whatever the bench's backend) from rt's G-buffer of the frame, untimed; its hit is on screen "
      "(in the view frustum and the surface the frame shows there), off screen (outside the frustum: beside the "
      "viewport or behind the camera), occluded (the frame shows another surface there) or a miss. Off screen + "
      "occluded is a lower bound on the rays any screen-space-first method traces for an exact mirror image; misses "
      "need none only if SSR reports them as misses (those leaving the view cannot be told from the screen). The last "
      "column counts the must-trace hits nearer than the resolve's fade end: the farther ones fade to nothing in the "
      "picture.\n\n"
      "![Pareto](charts/adaptive.png)\n",
      utc_timestamp(), options.command_line, context.renderer(), backend, options.width, options.height, options.warmup,
      kMeasuredRepeats, kIdenticalPsnr, reach_tracer_name);
  for (const nlohmann::json& scene : scene_entries)
    report += fmt::format("\n## {} (frames {})\n\n{}\n### Screen-space reach\n\n{}", scene["scene"].get<std::string>(),
                          scene["frames"].dump(), markdown_table(scene), reach_table(scene));
  if (!chart_note.empty()) report += "\n" + chart_note + "\n";
  write_file_atomically(out / "report.md", report);
  for (const nlohmann::json& scene : scene_entries) {
    const nlohmann::json& r = scene["screen_space_reach"]["all_frames"];
    fmt::print("{}  screen-space reach ({}): on screen {:.1f} %, off screen {:.1f} %, occluded {:.1f} %, miss {:.1f} %: "
               "must trace >= {:.1f} %\n",
               scene["scene"].get<std::string>(), scene["screen_space_reach"]["backend"].get<std::string>(),
               r["on_screen_percent"].get<double>(), r["off_screen_percent"].get<double>(),
               r["occluded_percent"].get<double>(), r["miss_percent"].get<double>(), r["must_trace_percent"].get<double>());
    for (const nlohmann::json& point : scene["configs"])
      fmt::print("  {:<10} {:9.3f} ms  {:6.3f} rays/px  SSIM {:.4f}  PSNR {:5.1f}{}\n",
                 point["label"].get<std::string>(), point["reflection_ms"].get<double>(),
                 point["rays_per_reflective_pixel"].get<double>(), point["ssim"].get<double>(),
                 point["psnr_db"].get<double>(), point["pareto"].get<bool>() ? "  pareto" : "");
  }
  return 0;
}

}  // namespace glint::bench
