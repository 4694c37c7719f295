#pragma once
// `glint render [scene]`: renders frames of a scene's walkthrough headless and writes PNG frames,
// timings.csv (one row per frame: GPU ms per pass, CPU frame ms, pixel counts), run.json (how the
// run was made), optionally debug views and an MP4. docs/render-command.md describes the outputs.
#include "render/frame_pipeline.h"

#include <CLI/CLI.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct RenderOptions {
  std::string scene = "atrium";
  std::string reflections = "hybrid";  // off|ssr|hybrid|rt|auto
  std::string backend = "cpu";         // ray tracing backend (hybrid, rt): cpu|embree|cuda|optix
  // cpu and cuda backends' BLAS builder (accel::builder_name); optix: optix-fasttrace|optix-fastbuild
  // (the default "sah" means optix-fasttrace there)
  std::string accel = "sah";
  std::string update = "auto";         // deformed meshes' structures: rebuild|refit|auto
  int width = 1280;
  int height = 720;
  // FrameSelection text, or "all"; empty (no --frames): a preview of kPreviewFrames frames spread over
  // the walkthrough (preview_frames). `glint bench` ignores it.
  std::string frames;
  std::string camera;             // "x,y,z": a fixed camera there instead of the walkthrough's (with target)
  std::string target;             // "x,y,z": what the fixed camera looks at (with camera)
  bool flat_normals = false;      // LoadOptions::flat_normals
  std::string out = "render-out";
  bool overwrite = false;         // replace an earlier run in `out` instead of refusing it
  bool debug_views = false;
  // png|exr: frames and debug views as 8-bit sRGB PNGs or as linear float EXRs (the colour before the
  // tone map; docs/render-command.md).
  std::string format = "png";
  bool video = false;
  bool timings_only = false;      // no images: timings.csv and run.json only (keeps the GPU busy)
  bool profile_scopes = false;    // also scopes.csv: every pass's nested scopes' GPU times per frame
  std::string deform = "on";      // on|off: animate the deformable meshes
  std::string deform_on;          // gpu|cpu; empty: gpu with --backend cuda or optix, cpu otherwise
  // --hold-frame N (FrameLoopOptions::hold_frame): camera, light and deformed meshes posed at
  // walkthrough frame N for every frame rendered, while the frame numbers (sampling, denoiser history)
  // advance; -1: off.
  int hold_frame = -1;
  // Resolve and SSR tunables most worth changing from the command line; the rest keep defaults.
  int blur_radius = 2;
  // Glossy reflections (docs/glossy.md): roughness on|off, reflection samples per pixel, the
  // roughness above which SSR leaves a pixel to rays, and the denoiser instead of the blur.
  std::string glossy = "off";
  int spp = 1;
  float roughness_cutoff = 0.6f;
  std::string denoise = "off";
  float exposure = 1.0f;
  std::string tone_map = "aces";
  int shadow_map_size = 1024;
  std::string shadow_cube_draw = "per-face";
  // The defaults of gbuffer and shadows are the fastest methods measured on the H100 and on llvmpipe
  // (docs/perf.md, "GPU-first frame"); glint bench keeps the paper's (raster, cube). primary's differs
  // by machine, so auto times both candidates on the first frame (render/primary_visibility_choice.h).
  std::string gbuffer = "visibility";  // raster|visibility (render::GBufferMethod)
  std::string primary = "auto";    // raster|rt|compute|auto (render::PrimaryVisibility; used with visibility)
  std::string shadows = "rt";      // cube|rt|hybrid (render::ShadowMethod)
  int ssr_max_steps = 256;
  float ssr_thickness = 0.01f;  // fraction of the view depth (SsrSettings::thickness)
  float ssr_confidence = 0.9f;
  // --reflections auto (render::AdaptiveSettings): rays per frame (-1: none) or milliseconds of
  // reflection work per frame (0: none), and the largest fraction of a tile's reflective pixels left
  // unreflected (SSR only).
  long long ray_budget = -1;
  double reflection_budget_ms = 0.0;
  float auto_quality = 0.0f;
  std::string command_line;       // for run.json, set by the CLI
};

// The frame pipeline's settings for `options`, checked: glint::Error with one line naming the flag for
// combinations that cannot run (--accel with embree, --deform-on gpu with a CPU backend). `glint
// bench` builds every cell's settings through it too.
render::FramePipelineSettings render_pipeline_settings(const RenderOptions& options);

// glint::Error (one line naming the flags) when `scene` has meshes to deform (--deform on) and rays
// are traced through a structure that cannot be refitted (--accel sbvh or kdtree) with --update
// refit or auto; checked once the scene is loaded, before anything is written, rather than at the
// first deformed frame. A static scene never refits, so it takes those structures with any --update.
void check_structure_follows_deformation(const RenderOptions& options, const render::FramePipelineSettings& settings,
                                         const Scene& scene);

// Whether the deformable meshes are posed on the GPU (--deform-on, resolved against --backend).
bool deforms_on_gpu(const RenderOptions& options);

// What `glint render` renders without --frames: kPreviewFrames frames spread evenly from the first
// to the last frame of the walkthrough (all of them when it is that short), ascending.
inline constexpr int kPreviewFrames = 8;
std::vector<int> preview_frames(int frame_count);

// "x,y,z" (three finite numbers, blanks allowed around them) -> the point; glint::Error naming `flag`
// otherwise.
vec3 parse_point_flag(std::string_view flag, std::string_view text);

void add_render_command(CLI::App& app, RenderOptions& options);
int run_render_command(const RenderOptions& options);

}  // namespace glint
