#include "render/frame_pipeline.h"

#include "core/error.h"
#include "core/stopwatch.h"
#include "gl/gl_check.h"
#include "render/debug_views.h"
#include "render/render_targets.h"
#include "render/scene_reflection_fade.h"
#include "render/texture_readback.h"

#include <algorithm>
#include <functional>
#include <cstring>

namespace glint::render {
namespace {

GlTexture make_reflection_image(int width, int height) {
  GlTexture texture = create_texture_2d(kReflectionFormat, width, height);
  check_gl("creating the reflection image");
  return texture;
}

void clear_reflection(GLuint texture) {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, zero);
  check_gl("clearing the reflection image");
}

// Validated, with the resolve's distance fade fitted to the scene (scene_reflection_fade.h).
FramePipelineSettings validated(const FramePipelineSettings& settings, const Scene& scene) {
  settings.validate();
  FramePipelineSettings fitted = settings;
  fitted.resolve = with_scene_fade(settings.resolve, scene);
  return fitted;
}

// hybrid shadows draw the cube map at their own, reduced size; the denoiser needs surface motion.
RasterSettings raster_settings(const FramePipelineSettings& settings) {
  RasterSettings raster = settings.raster;
  // The denoiser reprojects the deforming meshes by their own motion (render/surface_motion.h).
  if (settings.resolve.denoise) raster.surface_motion = true;
  if (settings.shadows.method == ShadowMethod::hybrid)
    raster.shadow_map_size = std::max(1, raster.shadow_map_size / settings.shadows.hybrid_cube_divisor);
  return raster;
}


// The part of a reflection image where the failure mask is `keep` (1: traced, 0: SSR), the rest 0.
ImageRgbaF masked(ImageRgbaF reflection, const ImageRgbaF& failure_mask, float keep) {
  for (std::size_t i = 0; i < reflection.pixels.size(); ++i)
    if (failure_mask.pixels[i].x != keep) reflection.pixels[i] = vec4(0.0f);
  return reflection;
}

}  // namespace

bool uses_ray_tracer(const FramePipelineSettings& settings) {
  return uses_ray_tracing(settings.reflections) || settings.shadows.method != ShadowMethod::cube ||
         settings.raster.primary == PrimaryVisibility::rt;
}

void FramePipelineSettings::validate() const {
  raster.validate();
  render::validate(ssr);
  render::validate(resolve);
  render::validate(sampling);
  shadows.validate();
  if (reflections == ReflectionMode::adaptive) adaptive.validate();
  if (reflections == ReflectionMode::adaptive && sampling.samples_per_pixel > 1)
    fail("frame pipeline: --spp {} needs reflections ssr, hybrid or rt (auto classifies one sample per frame)",
         sampling.samples_per_pixel);
  if (uses_ray_tracer(*this)) ray_tracing.validate();
}

FramePipeline::FramePipeline(const Scene& scene, int width, int height, const FramePipelineSettings& settings)
    : scene_(&scene),
      settings_(validated(settings, scene)),
      raster_(scene, width, height, raster_settings(settings_)),
      resolve_(width, height, settings_.resolve) {
  if (uses_ssr(settings_.reflections)) ssr_.emplace(width, height, settings_.ssr);
  if (uses_ray_tracer(settings_)) tracer_ = build_ray_tracer(scene, settings_.ray_tracing);
  if (settings_.raster.primary == PrimaryVisibility::rt) raster_.trace_primary_visibility(*tracer_);
  if (uses_ray_tracing(settings_.reflections))
    ray_traced_.emplace(scene, width, height, settings_.ray_tracing, *tracer_,
                        /*shadow_rays=*/settings_.shadows.method != ShadowMethod::cube);
  if (settings_.shadows.method != ShadowMethod::cube)
    shadow_rays_.emplace(scene, width, height, settings_.shadows.method, *tracer_,
                         settings_.ray_tracing.origin_offset_fraction, settings_.shadows.hybrid_depth_edge_fraction,
                         settings_.ray_tracing.gl_inline_shadow_rays);
  if (settings_.reflections == ReflectionMode::adaptive) {
    const bool device = tracer_->device_tracing() != nullptr || tracer_->gl_tracing() != nullptr;
    adaptive_.emplace(width, height, settings_.adaptive, device, length(scene.world_bounds().extent()));
    ssr_->set_tile_list(adaptive_->pass().ssr_tiles());
  }
  if (!ssr_) {
    own_reflection_ = make_reflection_image(width, height);
    clear_reflection(own_reflection_.id());
  }
  if (settings_.sampling.samples_per_pixel > 1 && settings_.reflections != ReflectionMode::off)
    sample_mean_.emplace(width, height);
}

void FramePipeline::upload_meshes(std::span<const std::uint32_t> dirty_meshes) {
  for (const std::uint32_t mesh : dirty_meshes)
    raster_.gpu_scene().update_mesh_vertices(mesh, scene_->meshes.at(mesh).positions, scene_->meshes.at(mesh).normals);
}

double FramePipeline::update_ray_tracer(std::span<const std::uint32_t> dirty_meshes) {
  if (!tracer_ || dirty_meshes.empty()) return 0.0;
  const Stopwatch watch;
  tracer_->update(*scene_, dirty_meshes, settings_.ray_tracing.update);
  return watch.elapsed_ms();
}

double FramePipeline::update_ray_tracer_on_device(std::span<const std::uint32_t> dirty_meshes) {
  if (!tracer_ || dirty_meshes.empty()) return 0.0;
  rt::DeviceTracing* device = tracer_->device_tracing();
  rt::GlTracing* gl = tracer_->gl_tracing();
  if (device == nullptr && gl == nullptr)
    fail("ray tracing: the {} backend cannot follow meshes deformed on the GPU", tracer_->name());
  const Stopwatch watch;
  // cuda and optix on their CUDA stream, gl in GL compute: either way only enqueued.
  if (device != nullptr) device->update_device(dirty_meshes, settings_.ray_tracing.update);
  else gl->update_gl(dirty_meshes, settings_.ray_tracing.update);
  return watch.elapsed_ms();
}

GLuint FramePipeline::reflection_image() const { return ssr_ ? ssr_->reflection() : own_reflection_.id(); }

void FramePipeline::render(const FrameState& frame, GpuTimer* timer) {
  const auto slot = static_cast<std::size_t>(frames_rendered_ % kFramesInFlight);
  RasterShadowSteps shadow;
  if (shadow_rays_) {
    // rt shadows need no cube map: reflection hits cast shadow rays too.
    shadow.cube = settings_.shadows.method == ShadowMethod::hybrid;
    // Traced inline (gl backend): the whole mask, in one dispatch; otherwise the rays, traced below.
    shadow.after_cube = [&] {
      if (shadow_rays_->traces_inline())
        shadow_rays_->run(raster_);
      else
        shadow_rays_->write_rays(raster_);
    };
  }
  const bool shadow_steps_left = shadow_rays_ && !shadow_rays_->traces_inline();
  raster_.render_surfaces(frame, timer, shadow);
  write_reflection_sampling(raster_.frame_constants_buffer(), settings_.sampling, 0);
  const ReflectionPath path = choose_reflection_path(frame, slot, timer);
  const bool marches = ssr_ && path != ReflectionPath::all_rays;
  // rt (and auto's all-rays frames): the ray tracer writes every reflective pixel of a cleared
  // image; hybrid: SSR's failed ones.
  const bool traces = ray_traced_ && path != ReflectionPath::all_ssr;
  const bool trace_all = traces && (!ssr_ || path == ReflectionPath::all_rays);
  const SsrInputs ssr_inputs{raster_.albedo_reflectivity(), raster_.world_position(), raster_.world_normal_roughness(),
                             raster_.lit(), raster_.frame_constants_buffer()};
  // A device backend that traces shadow and reflection rays traces both in one GL-CUDA hand-over
  // (about 0.3 ms each on an H100, docs/perf.md "Seventh round"): what needs only the G-buffer, up
  // to the traces, runs before lighting (docs/render.md "One hand-over a frame"). Otherwise the
  // frame keeps the paper's order, where SSR marches and fetches its colours in one dispatch.
  const bool one_hand_over = shadow_steps_left && traces && tracer_->device_tracing() != nullptr;
  const auto list_rays = [&] { ray_traced_->list(raster_, trace_all ? 0 : ssr_->failure_mask(), timer); };
  std::uint32_t listed = 0;
  if (one_hand_over) {
    if (marches) run_timed_pass(timer, "ssr", [&] { ssr_->march(ssr_inputs); });
    list_rays();
    listed = ray_traced_->trace(raster_, timer, [&] { shadow_rays_->start_trace(); });
    shadow_rays_->finish_trace();  // after the reflection rays: an unmap before more CUDA work is a round trip
    run_timed_pass(timer, "shadow", [&] { shadow_rays_->write_mask(raster_); });
    raster_.light(timer);
    if (marches) run_timed_pass(timer, "ssr", [&] { ssr_->shade(ssr_inputs); });
  } else {
    if (shadow_steps_left)
      run_timed_pass(timer, "shadow", [&] {
        shadow_rays_->trace();
        shadow_rays_->write_mask(raster_);
      });
    raster_.light(timer);
    if (marches) run_timed_pass(timer, "ssr", [&] { ssr_->run(ssr_inputs); });
    if (traces) {
      list_rays();
      listed = ray_traced_->trace(raster_, timer);
    }
  }
  if (marches) ssr_->request_counts(slot);  // outside the passes' time: a copy of 8 bytes and a fence
  if (traces) {
    if (trace_all) clear_reflection(reflection_image());
    ray_traced_->shade(raster_, reflection_image(), listed, timer);
  }
  if (adaptive_) adaptive_->finish_frame(slot);
  render_more_reflection_samples(slot);
  run_timed_pass(timer, "resolve",
                 [&] {
    resolve_.run({raster_.lit(), raster_.albedo_reflectivity(), reflection_image(), raster_.world_position(),
                  raster_.world_normal_roughness(), raster_.frame_constants_buffer(),
                  raster_.frame_constants().view_projection, raster_.world_motion()});
  });
  final_captured_[slot] = final_readback_.has_value();
  if (final_readback_)
    final_readback_->capture_texture(slot, resolve_.final_image(), GL_RGBA, GL_UNSIGNED_BYTE,
                                     final_readback_->slot_bytes());
  linear_captured_[slot] = linear_readback_.has_value();
  if (linear_readback_)
    linear_readback_->capture_texture(slot, resolve_.linear_image(), GL_RGBA, GL_FLOAT, linear_readback_->slot_bytes());
  ++frames_rendered_;
}

ReflectionPath FramePipeline::choose_reflection_path(const FrameState& frame, std::size_t slot, GpuTimer* timer) {
  if (!adaptive_) return ReflectionPath::per_tile;
  // --reflections auto: per-tile decisions, or a whole frame of rays or of SSR (adaptive_reflections.h).
  const ReflectionPath path = adaptive_->begin_frame(frame.camera, slot, ray_traced_->runs());
  const bool per_tile = path == ReflectionPath::per_tile;
  // Before SSR, which overwrites the failure mask the classification reads as last frame's.
  if (per_tile)
    run_timed_pass(timer, "classify", [&] {
      adaptive_->classify({raster_.albedo_reflectivity(), raster_.world_position(), ssr_->failure_mask(),
                           ssr_->reflection(), raster_.frame_constants().view_projection});
    });
  ssr_->set_tile_list(per_tile ? std::optional(adaptive_->pass().ssr_tiles()) : std::nullopt);
  ray_traced_->ray_list().set_tiles(
      per_tile ? std::optional(RayListTiles{adaptive_->pass().ray_tiles(), adaptive_->max_rays()}) : std::nullopt);
  return path;
}

void FramePipeline::render_more_reflection_samples(std::size_t slot) {
  if (!sample_mean_) return;
  const int samples = settings_.sampling.samples_per_pixel;
  RayTraceFrameStats total;
  auto count_rays = [&] {
    if (!ray_traced_) return;
    const std::optional<RayTraceFrameStats> stats = ray_traced_->take_stats(ray_traced_->runs() - 1, /*wait=*/true);
    total.rays_traced += stats->rays_traced;
    total.reflective_pixels = stats->reflective_pixels;
    total.trace_ms += stats->trace_ms;
    total.hit_shadow_trace_ms += stats->hit_shadow_trace_ms;
  };
  count_rays();
  sample_mean_->add(reflection_image(), 0, samples);
  for (int sample = 1; sample < samples; ++sample) {
    write_reflection_sampling(raster_.frame_constants_buffer(), settings_.sampling, sample);
    if (ssr_)
      ssr_->run({raster_.albedo_reflectivity(), raster_.world_position(), raster_.world_normal_roughness(), raster_.lit(),
                 raster_.frame_constants_buffer()});
    if (ray_traced_) {
      if (!ssr_) clear_reflection(own_reflection_.id());
      ray_traced_->run(raster_, ssr_ ? ssr_->failure_mask() : 0, reflection_image(), nullptr);
      count_rays();
    }
    sample_mean_->add(reflection_image(), sample, samples);
  }
  sampled_ray_stats_[slot] = total;
}

void FramePipeline::set_final_capture(bool on) {
  if (!on) {
    final_readback_.reset();
    return;
  }
  if (final_readback_) return;
  // kFinalFormat is RGBA8: its bytes are read as they are, exactly what read_final() quantises to.
  static_assert(kFinalFormat == GL_RGBA8);
  final_readback_.emplace(kFramesInFlight,
                          static_cast<std::size_t>(width()) * static_cast<std::size_t>(height()) * 4, "final image");
}

void FramePipeline::set_linear_capture(bool on) {
  resolve_.set_linear_output(on);
  if (!on) {
    linear_readback_.reset();
    return;
  }
  if (linear_readback_) return;
  static_assert(kLinearColourFormat == GL_RGBA32F);  // read as GL_FLOAT, bit for bit
  linear_readback_.emplace(kFramesInFlight, static_cast<std::size_t>(width()) * static_cast<std::size_t>(height()) *
                                                sizeof(vec4),
                           "linear image");
}

std::optional<FrameReadback> FramePipeline::take_readback(std::uint64_t frame, bool wait) {
  if (frame >= frames_rendered_ || frames_rendered_ - frame > kFramesInFlight)
    fail("frame pipeline: readback of frame {} asked after {} frames (the last {} are kept)", frame, frames_rendered_,
         kFramesInFlight);
  const auto slot = static_cast<std::size_t>(frame % kFramesInFlight);
  FrameReadback readback;
  // auto's whole-frame paths skip SSR (all rays) or the rays (all SSR).
  const ReflectionPath path = adaptive_ ? adaptive_->path(slot) : ReflectionPath::per_tile;
  if (ssr_ && path != ReflectionPath::all_rays) {
    readback.ssr_counts = ssr_->requested_counts(slot, wait);
    if (!readback.ssr_counts) return std::nullopt;
  }
  if (ray_traced_ && path != ReflectionPath::all_ssr) {
    // Pipeline frames and ray-traced runs go in step: every frame traces (auto knows its frame's run).
    // With --spp N > 1 every sample traced; render() summed them (waiting for each).
    const std::uint64_t run = adaptive_ ? *adaptive_->ray_run(slot) : ray_traced_->runs() - (frames_rendered_ - frame);
    readback.ray_stats = sample_mean_ ? sampled_ray_stats_[slot] : ray_traced_->take_stats(run, wait);
    if (!readback.ray_stats) return std::nullopt;
  }
  if (adaptive_) {
    readback.adaptive =
        adaptive_->take_stats(slot, wait, readback.ssr_counts,
                              readback.ray_stats ? std::optional(readback.ray_stats->reflective_pixels) : std::nullopt);
    if (!readback.adaptive) return std::nullopt;
  }
  if (final_readback_ && final_captured_[slot]) {
    const std::span<const std::byte> bytes = final_readback_->read(slot, wait);
    if (bytes.empty()) return std::nullopt;
    ImageRgba8 image(width(), height());
    const std::size_t row_bytes = static_cast<std::size_t>(width()) * 4;
    for (int y = 0; y < height(); ++y)  // GL's rows are bottom first
      std::memcpy(image.pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width()),
                  bytes.data() + static_cast<std::size_t>(height() - 1 - y) * row_bytes, row_bytes);
    readback.final_image = std::move(image);
  }
  if (linear_readback_ && linear_captured_[slot]) {
    const std::span<const std::byte> bytes = linear_readback_->read(slot, wait);
    if (bytes.empty()) return std::nullopt;
    ImageRgbaF image(width(), height());
    const std::size_t row_bytes = static_cast<std::size_t>(width()) * sizeof(vec4);
    for (int y = 0; y < height(); ++y)  // GL's rows are bottom first
      std::memcpy(image.pixels.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width()),
                  bytes.data() + static_cast<std::size_t>(height() - 1 - y) * row_bytes, row_bytes);
    readback.linear_image = std::move(image);
  }
  return readback;
}

void FramePipeline::observe(const FrameTimes& times, const FrameReadback& readback) {
  if (!adaptive_) return;
  CostSample sample;
  for (const PassTime& pass : times.passes) {
    if (pass.name == "ssr") sample.ssr_ms += pass.milliseconds;
    if (pass.name == "ray_list" || pass.name == "hit_shade") sample.ray_ms += pass.milliseconds;
    if (pass.name == "classify") sample.classify_ms += pass.milliseconds;
  }
  if (readback.ssr_counts) sample.ssr_pixels = readback.ssr_counts->reflective;
  if (readback.ray_stats) {
    sample.rays = readback.ray_stats->rays_traced;
    sample.ray_ms += readback.ray_stats->trace_ms;  // every backend's trace, the gl backend's pass too
  }
  adaptive_->observe(sample);
}

ImageRgba8 FramePipeline::read_final() const {
  return quantize_to_rgba8(read_texture_rgbaf(resolve_.final_image(), kFinalFormat, width(), height()));
}

ImageRgbaF FramePipeline::read_linear() const {
  if (resolve_.linear_image() == 0)
    fail("frame pipeline: read_linear() needs set_linear_capture(true) before the frame is rendered");
  return read_texture_rgbaf(resolve_.linear_image(), kLinearColourFormat, width(), height());
}

std::optional<RayTraceFrameStats> FramePipeline::ray_trace_stats() {
  if (!ray_traced_ || ray_traced_->runs() == 0) return std::nullopt;
  if (sample_mean_) return sampled_ray_stats_[static_cast<std::size_t>((frames_rendered_ - 1) % kFramesInFlight)];
  return ray_traced_->frame_stats();
}

std::optional<SsrCounts> FramePipeline::read_counts() const {
  if (!ssr_) return std::nullopt;
  return ssr_->read_counts();
}

std::vector<DebugView> FramePipeline::read_debug_views() const {
  std::vector<DebugView> views;
  const ImageRgbaF albedo = raster_.read_rgbaf(RasterOutput::AlbedoReflectivity);
  const ImageRgbaF normals = raster_.read_rgbaf(RasterOutput::WorldNormalRoughness);
  const ImageRgbaF positions = raster_.read_rgbaf(RasterOutput::WorldPosition);
  const ImageRgbaF shadow_mask = raster_.read_rgbaf(RasterOutput::ShadowMask);
  views.push_back({"albedo", albedo_view(albedo), opaque(albedo)});
  views.push_back({"normals", normal_view(normals), opaque(normals)});
  views.push_back({"positions", position_view(positions, scene_->world_bounds()), opaque(positions)});
  views.push_back({"depth", depth_view(positions, raster_.frame_constants()),
                   view_depth(positions, raster_.frame_constants())});
  views.push_back({"shadow_mask", grey_view(shadow_mask), red_as_grey(shadow_mask)});
  if (settings_.reflections == ReflectionMode::off) return views;
  if (adaptive_) {
    ImageRgba8 classes =
        tile_class_view(adaptive_->last_classes(albedo, positions), adaptive_->pass().tile_columns(), width(), height());
    ImageRgbaF colours = unit_colours(classes);
    views.push_back({"tile_classes", std::move(classes), std::move(colours)});
  }

  const ImageRgbaF reflection = read_texture_rgbaf(reflection_image(), kReflectionFormat, width(), height());
  if (!ssr_) {
    views.push_back({"traced_reflection", reflection_view(reflection), opaque(reflection)});
    return views;
  }
  ImageRgbaF failure_mask = read_texture_rgbaf(ssr_->failure_mask(), kFailureMaskFormat, width(), height());
  // auto: SSR wrote the mask in its own tiles only; rays-only tiles are traced wherever reflective.
  if (adaptive_)
    mark_traced_tiles(failure_mask, adaptive_->last_classes(albedo, positions), adaptive_->pass().tile_columns());
  // Hit shading writes exactly the failed pixels, so the mask splits the image into its two sources.
  const ImageRgbaF from_ssr = masked(reflection, failure_mask, 0.0f);
  views.push_back({"ssr_reflection", reflection_view(from_ssr), opaque(from_ssr)});
  views.push_back({"failure_mask", grey_view(failure_mask), red_as_grey(failure_mask)});
  if (ray_traced_) {
    const ImageRgbaF traced = masked(reflection, failure_mask, 1.0f);
    views.push_back({"traced_reflection", reflection_view(traced), opaque(traced)});
    views.push_back({"reflection", reflection_view(reflection), opaque(reflection)});
  }
  return views;
}

}  // namespace glint::render
