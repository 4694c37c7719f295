#pragma once
// One frame of glint's renderer: the raster passes (G-buffer, shadow, light), SSR (ssr and hybrid
// modes), the ray-traced complement (hybrid: SSR-failed pixels; rt: every reflective pixel; see
// ray_traced_reflections.h), then resolve (fade, blur, composite, tone map). When a device backend
// traces shadow and reflection rays, what needs only the G-buffer (SSR's march, the ray list, every
// trace) runs before lighting, so that the traces share one GL-CUDA hand-over (docs/render.md "One
// hand-over a frame"). Every GPU
// pass is timed under its name in kFramePassNames when a GpuTimer is given; the frame's final image
// stays on the GPU until read_final() copies it out.
//
//   FramePipeline pipeline(scene, 1280, 720, settings);
//   timer.begin_frame();
//   pipeline.render(animation.at(frame), &timer);
//   timer.end_frame();
//   write_png(path, pipeline.read_final());
//
// Pipelined use (app/frame_loop.h): render() also queues copies of the frame's counters (and, with
// set_final_capture(true), of its final image) into readback slots, one per frame in flight
// (gl/readback_ring.h), and take_readback(n) reads frame n's frames later without stalling.
#include "core/image.h"
#include "gl/gl_objects.h"
#include "gl/gpu_timer.h"
#include "gl/readback_ring.h"
#include "render/adaptive_reflections.h"
#include "render/raster_pipeline.h"
#include "render/raster_settings.h"
#include "render/ray_traced_reflections.h"
#include "render/ray_traced_shadows.h"
#include "render/reflection_mode.h"
#include "render/reflection_accumulation.h"
#include "render/reflection_sampling.h"
#include "render/resolve_pass.h"
#include "render/resolve_settings.h"
#include "render/shadow_method.h"
#include "render/ssr_pass.h"
#include "render/ssr_settings.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint::render {

// Timer names of the passes, in the order timings.csv lists them (not the order they run:
// the shadow mask needs the G-buffer, so "gbuffer" runs first).
// A device backend's "device_trace" pass (its reflection trace with the hits' shadow rays, as GL
// sees it) has no column of its own: it counts in gpu_total_ms, and --profile-scopes shows it.
inline constexpr std::string_view kFramePassNames[] = {"shadow",   "gbuffer",   "light",  "ssr",
                                                       "ray_list", "hit_shade", "resolve"};

struct FramePipelineSettings {
  ReflectionMode reflections = ReflectionMode::ssr;
  RasterSettings raster;
  SsrSettings ssr;
  ResolveSettings resolve;
  RayTracingSettings ray_tracing;  // hybrid and rt reflections, rt and hybrid shadows
  ShadowSettings shadows;          // cube (default), rt or hybrid
  AdaptiveSettings adaptive;       // --reflections auto: budget, quality target
  ReflectionSamplingSettings sampling;  // glossy or mirror, samples per pixel, SSR roughness cutoff (docs/glossy.md)

  void validate() const;  // throws glint::Error naming the first bad setting
};

// Whether the settings need a ray tracer: hybrid or rt reflections, rt or hybrid shadows, or rt
// primary visibility.
bool uses_ray_tracer(const FramePipelineSettings& settings);

// What a frame counted (and, with final capture, its final image), read back after the GPU finished it.
struct FrameReadback {
  std::optional<SsrCounts> ssr_counts;           // with SSR
  std::optional<RayTraceFrameStats> ray_stats;   // with ray tracing
  std::optional<ImageRgba8> final_image;         // with set_final_capture(true): read_final()'s pixels
  std::optional<ImageRgbaF> linear_image;        // with set_linear_capture(true): read_linear()'s pixels
  std::optional<AdaptiveFrameStats> adaptive;    // --reflections auto: what its tiles were
};

// An image a frame produced besides the final one, made viewable as 8-bit RGBA, and the linear
// values it shows (debug_views.h says which: raw albedo, normals, positions, view depth, masks,
// reflection radiance; a = 1), for `glint render --format exr`.
struct DebugView {
  std::string name;  // file-name friendly: "albedo", "normals", ...
  ImageRgba8 image;
  ImageRgbaF linear;
};

class FramePipeline {
public:
  // Uploads `scene` (which must outlive the pipeline, see RasterPipeline), compiles every pass and,
  // in hybrid and rt reflection modes or with rt and hybrid shadows, builds the one ray tracer both
  // use. Needs a current GL context.
  FramePipeline(const Scene& scene, int width, int height, const FramePipelineSettings& settings = {});

  // After the vertices of `dirty_meshes` moved in the scene (SceneDeformers::apply's list): copies
  // them to the GPU scene in place.
  void upload_meshes(std::span<const std::uint32_t> dirty_meshes);
  // ... and brings the ray tracer's structures up to date by the settings' UpdatePolicy. Returns its
  // wall time in milliseconds (0 without ray tracing).
  double update_ray_tracer(std::span<const std::uint32_t> dirty_meshes);
  // The same after a GPU deformer (render/gpu_deformation.h) moved the meshes on the GPU: the tracer's
  // DeviceTracing::update_device (cuda, optix) or GlTracing::update_gl (gl), enqueued.
  double update_ray_tracer_on_device(std::span<const std::uint32_t> dirty_meshes);

  // In hybrid and rt modes with a CPU backend, the CPU waits for the ray list in the middle of the
  // frame; with a GPU backend (cuda) nothing waits.
  void render(const FrameState& frame, GpuTimer* timer = nullptr);

  // Frames render() was called for; frame n (0, 1, ...) is the (n+1)-th call.
  std::uint64_t frames_rendered() const { return frames_rendered_; }
  // On: every later render() also copies its final image into a pixel-pack readback slot.
  void set_final_capture(bool on);
  // On: the resolve also stores every frame's linear colour (exposure x (lit + reflectivity x
  // reflection), the tone map's input) and render() copies it into a readback slot as RGBA32F.
  void set_linear_capture(bool on);
  // Frame `frame`'s counters (and captured image), one of the last kFramesInFlight frames rendered:
  // nullopt while the GPU has not finished their copies and `wait` is false; with `wait` it waits.
  // glint::Error for an older or a future frame.
  std::optional<FrameReadback> take_readback(std::uint64_t frame, bool wait);
  // A finished frame's pass times and counts (FrameLoop calls it as it reads them): --reflections
  // auto's cost model learns from them; nothing happens in the other modes.
  void observe(const FrameTimes& times, const FrameReadback& readback);
  // --reflections auto's tile decisions; null in the other modes.
  const AdaptiveReflections* adaptive() const { return adaptive_ ? &*adaptive_ : nullptr; }

  // The last frame's output, sRGB-encoded, top row first. Waits for the GPU.
  ImageRgba8 read_final() const;
  // The last frame's linear colour, the tone map's input, top row first (a = 1): needs
  // set_linear_capture(true) before that frame (glint::Error otherwise). Waits for the GPU.
  ImageRgbaF read_linear() const;
  // The texture read_final() reads (kFinalFormat, bottom row first), rewritten by every render(): for
  // showing a frame on the same context without a host round trip (the viewer copies it on the GPU).
  GLuint final_texture() const { return resolve_.final_image(); }
  // Reflective and SSR-failed pixels of the last frame; nullopt when reflections are off (SSR did not
  // run, so nothing was counted). Waits for the GPU.
  std::optional<SsrCounts> read_counts() const;
  // Rays traced and the trace time of the last frame; nullopt without ray tracing or before the
  // first frame. With a GPU backend, waits for the frame's GPU work.
  std::optional<RayTraceFrameStats> ray_trace_stats();
  // The ray tracer (hybrid and rt reflections, rt and hybrid shadows), for its build/update
  // statistics; null otherwise.
  const rt::RayTracer* ray_tracer() const { return tracer_.get(); }
  // A GPU ray tracer's device side (for a GPU deformer); null with a CPU backend or no ray tracing.
  rt::DeviceTracing* device_tracing() { return tracer_ ? tracer_->device_tracing() : nullptr; }
  rt::GlTracing* gl_tracing() { return tracer_ ? tracer_->gl_tracing() : nullptr; }
  // The shadow rays (rt and hybrid shadows), for tests; null with cube shadows.
  const RayTracedShadows* shadow_rays() const { return shadow_rays_ ? &*shadow_rays_ : nullptr; }
  // The ray-traced reflections (hybrid and rt reflections), for tests; null otherwise.
  const RayTracedReflections* ray_traced_reflections() const { return ray_traced_ ? &*ray_traced_ : nullptr; }
  // albedo, normals, positions, depth, shadow mask; with SSR its reflection and failure mask; with ray
  // tracing the traced reflection; with both the combined reflection. Waits for the GPU; see
  // debug_views.h for how each is made viewable.
  std::vector<DebugView> read_debug_views() const;

  RasterPipeline& raster() { return raster_; }
  const RasterPipeline& raster() const { return raster_; }
  const FramePipelineSettings& settings() const { return settings_; }
  int width() const { return raster_.width(); }
  int height() const { return raster_.height(); }

private:
  GLuint reflection_image() const;  // what resolve reads
  // --spp N > 1 (docs/glossy.md): samples 1 .. N-1 of the reflections after the frame's first one
  // (untimed), averaged with it into reflection_image(); their rays counted into sampled_ray_stats_.
  // auto's choice for the frame, after its tile classification (per_tile without auto).
  ReflectionPath choose_reflection_path(const FrameState& frame, std::size_t slot, GpuTimer* timer);
  void render_more_reflection_samples(std::size_t slot);

  const Scene* scene_;
  FramePipelineSettings settings_;
  RasterPipeline raster_;
  std::optional<SsrPass> ssr_;
  std::unique_ptr<rt::RayTracer> tracer_;  // shared by ray_traced_ and shadow_rays_
  std::optional<RayTracedReflections> ray_traced_;
  std::optional<AdaptiveReflections> adaptive_;  // --reflections auto
  std::optional<RayTracedShadows> shadow_rays_;
  ResolvePass resolve_;
  // The reflection image when SSR does not make one: all zero (off), or cleared and filled by the
  // ray tracer every frame (rt). In hybrid the ray tracer fills SSR's failed pixels instead.
  GlTexture own_reflection_;
  std::uint64_t frames_rendered_ = 0;
  std::optional<ReadbackRing> final_readback_;  // with final capture: RGBA8, rows bottom first
  std::array<bool, kFramesInFlight> final_captured_{};  // per slot: that frame's image was captured
  std::optional<ReadbackRing> linear_readback_;  // with linear capture: RGBA32F, rows bottom first
  std::array<bool, kFramesInFlight> linear_captured_{};
  std::optional<ReflectionAccumulation> sample_mean_;  // with --spp N > 1
  std::array<RayTraceFrameStats, kFramesInFlight> sampled_ray_stats_{};  // per slot, with --spp N > 1
};

}  // namespace glint::render
