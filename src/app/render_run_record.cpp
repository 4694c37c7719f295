#include "app/render_run_record.h"

#include "backends/registry.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/untrusted_text.h"
#include "core/utc_timestamp.h"
#include "render/frame_pipeline.h"
#include "render/scene_reflection_fade.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>

namespace glint {
namespace {


constexpr double kBytesPerMegabyte = 1024.0 * 1024.0;

CsvField megabytes_field(std::optional<std::uint64_t> bytes) {
  return bytes ? CsvField(static_cast<double>(*bytes) / kBytesPerMegabyte) : CsvField("");
}

// {"after_first_frame", "after_last_frame", "peak"} in MiB, or null when the memory was not sampled.
nlohmann::json memory_summary(std::optional<std::uint64_t> first, std::optional<std::uint64_t> last,
                              std::optional<std::uint64_t> peak) {
  if (!first) return nullptr;
  return {{"after_first_frame", static_cast<double>(*first) / kBytesPerMegabyte},
          {"after_last_frame", static_cast<double>(*last) / kBytesPerMegabyte},
          {"peak", static_cast<double>(*peak) / kBytesPerMegabyte}};
}

// The distance fade the frames used (render/scene_reflection_fade.h), in world units, and whence.
nlohmann::json reflection_fade_summary(const Scene& scene) {
  const DistanceFade fade = render::scene_reflection_fade(scene);
  return {{"start", fade.start},
          {"end", fade.end},
          {"from", scene.reflection_fade ? "the scene" : "the scene's bounds diagonal"}};
}

nlohmann::json scene_summary(const Scene& scene) {
  return {{"name", untrusted_text(scene.name)},  // from the scene file: bounded, escaped
          {"source", scene.source},
          {"meshes", scene.meshes.size()},
          {"instances", scene.instances.size()},
          {"materials", scene.materials.size()},
          {"textures", scene.textures.size()},
          {"vertices", scene.vertex_count()},
          {"triangles", scene.triangle_count()},
          {"deformable_meshes", scene.deformable_meshes().size()},
          {"walkthrough_frames", scene.walkthrough.frame_count},
          {"reflection_fade", reflection_fade_summary(scene)}};
}

nlohmann::json options_summary(const RenderOptions& options) {
  return {{"reflections", options.reflections},
          {"backend", options.backend},
          {"accel", options.accel},
          {"update", options.update},
          {"deform", options.deform},
          {"deform_on", deforms_on_gpu(options) ? "gpu" : "cpu"},
          {"hold_frame", options.hold_frame >= 0 ? nlohmann::json(options.hold_frame) : nlohmann::json(nullptr)},
          {"debug_views", options.debug_views},
          {"format", options.format},
          {"video", options.video},
          {"timings_only", options.timings_only},
          {"profile_scopes", options.profile_scopes},
          {"blur_radius", options.blur_radius},
          {"glossy", options.glossy},
          {"spp", options.spp},
          {"roughness_cutoff", options.roughness_cutoff},
          {"denoise", options.denoise},
          {"exposure", options.exposure},
          {"tone_map", options.tone_map},
          {"shadow_map_size", options.shadow_map_size},
          {"shadow_cube_draw", options.shadow_cube_draw},
          {"gbuffer", options.gbuffer},
          {"primary", options.primary},
          {"shadows", options.shadows},
          {"ssr_max_steps", options.ssr_max_steps},
          {"ssr_thickness", options.ssr_thickness},
          {"ssr_confidence", options.ssr_confidence},
          {"ray_budget", options.ray_budget >= 0 ? nlohmann::json(options.ray_budget) : nlohmann::json(nullptr)},
          {"reflection_budget_ms",
           options.reflection_budget_ms > 0.0 ? nlohmann::json(options.reflection_budget_ms) : nlohmann::json(nullptr)},
          {"auto_quality", options.auto_quality}};
}

}  // namespace

RenderRunRecord::RenderRunRecord(const RenderOptions& options, const Scene& scene, const HeadlessGlContext& context,
                                 PassTimingMethod pass_timing, const std::vector<int>& frames)
    : triangles_(scene.triangle_count()) {
  run_["command"] = options.command_line;
  run_["glint_version"] = GLINT_VERSION;
  run_["date"] = utc_timestamp();
  run_["scene"] = scene_summary(scene);
  run_["gl"] = {{"renderer", context.renderer()},
                {"vendor", context.vendor()},
                {"version", context.version()},
                {"egl_device", context.device_index()},
                {"pass_timing", pass_timing_name(pass_timing)}};
  run_["resolution"] = {options.width, options.height};
  run_["frames"] = {{"selection", options.frames.empty() ? "all" : options.frames},
                    {"count", frames.size()},
                    {"first", frames.empty() ? -1 : frames.front()},
                    {"last", frames.empty() ? -1 : frames.back()}};
  run_["options"] = options_summary(options);
}

std::vector<std::string> RenderRunRecord::timings_header() {
  std::vector<std::string> header{"frame"};
  for (const std::string_view pass : render::kFramePassNames) header.push_back(std::string(pass) + "_ms");
  for (const char* column : {"gpu_total_ms", "frame_ms", "frame_latency_ms", "deform_ms", "accel_update_ms", "trace_ms", "triangles",
                             "reflective_pixels", "ssr_failed_pixels", "rays_traced", "resident_mb",
                             "gpu_memory_used_mb"})
    header.emplace_back(column);
  // --reflections auto (docs/hybrid.md "auto"): its tile classification pass, tiles per class, the
  // frame's ray budget after camera motion (empty: none), motion's share of it, rays asked for.
  for (const char* column : {"classify_ms", "tiles_none", "tiles_ssr_only", "tiles_ssr_fallback", "tiles_rt_only",
                             "ray_budget", "budget_factor", "rays_wanted"})
    header.emplace_back(column);
  // Of trace_ms, the hits' shadow rays traced with the hits (cuda and optix with rt or hybrid
  // shadows; the last column so that the earlier ones keep their places).
  header.emplace_back("hit_shadow_trace_ms");
  return header;
}

std::vector<CsvField> RenderRunRecord::add_frame(const Frame& frame) {
  std::vector<CsvField> row{frame.frame};
  std::map<std::string, double> recorded;
  double gpu_total_ms = 0.0;
  for (const std::string_view pass : render::kFramePassNames) {
    std::optional<double> ms;
    for (const PassTime& time : frame.times.passes)
      if (time.name == pass) ms = ms.value_or(0.0) + time.milliseconds;
    if (ms) {
      row.emplace_back(*ms);
      gpu_total_ms += *ms;
      recorded[std::string(pass) + "_ms"] = *ms;
    } else {
      row.emplace_back("");
    }
  }
  // Passes without a column of their own count in the total too (the gl backend's "trace", which
  // timings.csv gives as trace_ms; cuda's and optix's "device_trace", frame_pipeline.h).
  for (const PassTime& time : frame.times.passes)
    if (std::find(std::begin(render::kFramePassNames), std::end(render::kFramePassNames), time.name) ==
        std::end(render::kFramePassNames))
      gpu_total_ms += time.milliseconds;
  const auto& ssr = frame.ssr_counts;
  const auto& rays = frame.ray_stats;
  row.emplace_back(gpu_total_ms);
  row.emplace_back(frame.frame_ms);
  row.emplace_back(frame.latency_ms);
  row.emplace_back(frame.deform_ms);
  row.emplace_back(frame.accel_update_ms ? CsvField(*frame.accel_update_ms) : CsvField(""));
  row.emplace_back(rays ? CsvField(rays->trace_ms) : CsvField(""));
  row.emplace_back(triangles_);
  const auto& adaptive = frame.adaptive;
  // auto's SSR and ray list see only their tiles: the classification counted every reflective pixel.
  row.emplace_back(adaptive ? CsvField(adaptive->reflective_pixels)
                   : ssr    ? CsvField(ssr->reflective)
                   : rays   ? CsvField(rays->reflective_pixels)
                            : CsvField(""));
  row.emplace_back(ssr ? CsvField(ssr->failed) : CsvField(""));
  row.emplace_back(rays ? CsvField(rays->rays_traced) : CsvField(""));
  row.emplace_back(megabytes_field(frame.resident_bytes));
  row.emplace_back(megabytes_field(frame.gpu_memory_used_bytes));
  std::optional<double> classify_ms;
  for (const PassTime& time : frame.times.passes)
    if (time.name == "classify") classify_ms = classify_ms.value_or(0.0) + time.milliseconds;
  row.emplace_back(classify_ms ? CsvField(*classify_ms) : CsvField(""));
  for (std::size_t c = 0; c < render::kTileClassCount; ++c)
    row.emplace_back(adaptive ? CsvField(adaptive->class_tiles[c]) : CsvField(""));
  row.emplace_back(adaptive && adaptive->ray_budget ? CsvField(*adaptive->ray_budget) : CsvField(""));
  row.emplace_back(adaptive ? CsvField(static_cast<double>(adaptive->budget_factor)) : CsvField(""));
  row.emplace_back(adaptive ? CsvField(adaptive->rays_wanted) : CsvField(""));
  row.emplace_back(rays ? CsvField(rays->hit_shadow_trace_ms) : CsvField(""));
  if (classify_ms) recorded["classify_ms"] = *classify_ms;
  resident_.add(frame.resident_bytes);
  gpu_memory_.add(frame.gpu_memory_used_bytes);
  recorded["gpu_total_ms"] = gpu_total_ms;
  recorded["frame_ms"] = frame.frame_ms;
  recorded["frame_latency_ms"] = frame.latency_ms;
  recorded["deform_ms"] = frame.deform_ms;
  if (frame.accel_update_ms) recorded["accel_update_ms"] = *frame.accel_update_ms;
  if (rays) {
    recorded["trace_ms"] = rays->trace_ms;
    recorded["hit_shadow_trace_ms"] = rays->hit_shadow_trace_ms;
    recorded["rays_traced"] = rays->rays_traced;
  }
  if (frames_recorded_++ == 0)
    first_frame_ = std::move(recorded);
  else
    for (const auto& [column, value] : recorded) later_sums_[column] += value;
  return row;
}

void RenderRunRecord::add_row(const std::vector<std::string>& row) {
  const std::vector<std::string> header = timings_header();
  if (row.size() != header.size())
    fail("timings row of another rank: {} fields, expected {}", row.size(), header.size());
  std::map<std::string, double> recorded;
  std::optional<std::uint64_t> resident, gpu_memory;
  const auto bytes = [](double megabytes) { return static_cast<std::uint64_t>(megabytes * kBytesPerMegabyte + 0.5); };
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& column = header[i];
    if (row[i].empty()) continue;  // a pass that did not run, a count not made
    const double value = std::strtod(row[i].c_str(), nullptr);
    if (column == "resident_mb") resident = bytes(value);
    else if (column == "gpu_memory_used_mb") gpu_memory = bytes(value);
    // add_frame's means are over the times (the *_ms columns) and the rays traced, not the other counts.
    else if (column.ends_with("_ms") || column == "rays_traced") recorded[column] = value;
  }
  resident_.add(resident);
  gpu_memory_.add(gpu_memory);
  if (frames_recorded_++ == 0)
    first_frame_ = std::move(recorded);
  else
    for (const auto& [column, value] : recorded) later_sums_[column] += value;
}

void RenderRunRecord::MemorySamples::add(std::optional<std::uint64_t> bytes) {
  if (!bytes) return;
  if (!first) first = bytes;
  last = bytes;
  peak = std::max(peak.value_or(0), *bytes);
}

void RenderRunRecord::mark_interrupted(const char* signal) { run_["interrupted_by"] = signal; }

namespace {

// The structure the tracer built: glint's builder, or the backend's own (its default when none was named).
std::string recorded_structure(const render::RayTracingSettings& settings) {
  const backends::Backend& backend = backends::find_backend(settings.backend);
  if (!backend.structures.empty())
    return settings.accel.backend_structure.empty() ? backend.structures.front() : settings.accel.backend_structure;
  return std::string(accel::builder_name(settings.accel.builder));
}

}  // namespace

nlohmann::json primary_visibility_record(const render::RasterPipeline& raster) {
  if (raster.settings().gbuffer != render::GBufferMethod::visibility) return nullptr;
  nlohmann::json record = {{"method", render::primary_visibility_name(raster.primary_visibility())}};
  if (const std::optional<render::PrimaryVisibilityChoice>& choice = raster.primary_visibility_choice()) {
    if (choice->raster_ms && choice->compute_ms) {
      record["chosen_by"] = fmt::format("--primary auto: both timed on the first frame; compute kept only when {}x "
                                        "faster",
                                        render::kComputeRasterMargin);
      record["raster_ms"] = *choice->raster_ms;
      record["compute_ms"] = *choice->compute_ms;
    } else {
      record["chosen_by"] = "--primary auto on a software GL renderer: the id draw, untimed";
    }
  }
  return record;
}

void RenderRunRecord::set_ray_tracer(const render::RayTracingSettings& settings, const rt::RayTracerStats& stats) {
  run_["ray_tracer"] = {{"backend", settings.backend},
                        {"accel", recorded_structure(settings)},
                        {"update", std::string(rt::update_policy_name(settings.update))},
                        {"build_ms", stats.build_ms},
                        {"memory_bytes", stats.memory_bytes}};
}

void RenderRunRecord::write(const std::filesystem::path& path, double wall_ms,
                            const std::optional<rt::RayTracerStats>& final_tracer_stats) const {
  nlohmann::json run = run_;
  if (final_tracer_stats) {
    run["ray_tracer"]["rebuilds"] = final_tracer_stats->rebuilds;
    run["ray_tracer"]["refits"] = final_tracer_stats->refits;
    if (final_tracer_stats->blas_sah_drift) run["ray_tracer"]["final_blas_sah_drift"] = *final_tracer_stats->blas_sah_drift;
  }
  const std::size_t skipped = frames_recorded_ > 1 ? 1 : 0;
  const std::map<std::string, double>& sums = skipped ? later_sums_ : first_frame_;
  nlohmann::json means = nlohmann::json::object();
  const double counted = static_cast<double>(frames_recorded_ - skipped);
  for (const auto& [column, sum] : sums) means[column] = sum / counted;
  run["mean_per_frame"] = means;
  run["mean_excludes_first_frames"] = skipped;
  run["frames_rendered"] = frames_recorded_;
  run["memory_mb"] = {{"resident", memory_summary(resident_.first, resident_.last, resident_.peak)},
                      {"gpu_used", memory_summary(gpu_memory_.first, gpu_memory_.last, gpu_memory_.peak)}};
  run["wall_seconds"] = wall_ms / 1000.0;
  write_file_atomically(path, run.dump(2) + "\n");
}

}  // namespace glint
