#include "app/render_command.h"

#include "app/frame_loop.h"
#include "app/frame_selection.h"
#include "app/info_command.h"
#include "app/mpi/mpi_world.h"
#include "app/mpi/rank_devices.h"
#include "app/mpi/render_share.h"
#include "app/output_folder.h"
#include "app/frame_image_files.h"
#include "app/image_writer_thread.h"
#include "app/render_run_record.h"
#include "app/video_writer.h"
#include "backends/registry.h"
#include "core/csv_writer.h"
#include "core/error.h"
#include "core/interruption.h"
#include "core/log.h"
#include "core/progress_bar.h"
#include "core/stopwatch.h"
#include "gl/egl_context.h"
#include "accel/builders/builder.h"
#include "render/frame_pipeline.h"
#include "rt/ray_tracer.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace glint {
namespace {

// Whether --backend names the gl backend (its structures in the renderer's GL context).
bool is_gl_backend(const RenderOptions& options) {
  const backends::Backend* backend = backends::backend_if_known(options.backend);
  return backend != nullptr && backend->device == backends::Device::gl;
}

std::string builder_names() {
  std::string names;
  for (const std::string& name : rt::blas_structure_names()) {
    if (!names.empty()) names += ", ";
    names += name;
  }
  return names;
}

// --accel's help for the backends with structures of their own: "; of the optix backend:
// optix-fasttrace (the default there) or optix-fastbuild".
std::string own_structures_help() {
  std::string text;
  for (const backends::Backend& backend : backends::all_backends()) {
    if (backend.structures.empty()) continue;
    text += fmt::format("; of the {} backend: {} (the default there)", backend.name, backend.structures.front());
    for (std::size_t i = 1; i < backend.structures.size(); ++i)
      text += (i + 1 == backend.structures.size() ? " or " : ", ") + backend.structures[i];
  }
  return text;
}

}  // namespace

render::FramePipelineSettings render_pipeline_settings(const RenderOptions& options) {
  render::FramePipelineSettings settings;
  settings.reflections = render::parse_reflection_mode(options.reflections);
  settings.raster.shadow_map_size = options.shadow_map_size;
  settings.raster.shadow_cube_draw = render::parse_shadow_cube_draw(options.shadow_cube_draw);
  settings.raster.gbuffer = render::parse_gbuffer_method(options.gbuffer);
  settings.raster.primary = render::parse_primary_visibility(options.primary);
  settings.shadows.method = render::parse_shadow_method(options.shadows);
  settings.ssr.max_steps = options.ssr_max_steps;
  settings.ssr.thickness = options.ssr_thickness;
  settings.ssr.confidence_threshold = options.ssr_confidence;
  if (options.ray_budget >= 0)
    settings.adaptive.budget.rays = static_cast<std::uint32_t>(std::min<long long>(options.ray_budget, 0xffffffffLL));
  if (options.reflection_budget_ms > 0.0) settings.adaptive.budget.ms = options.reflection_budget_ms;
  settings.adaptive.max_unreflected_fraction = options.auto_quality;
  settings.resolve.blur_radius = options.blur_radius;
  settings.resolve.denoise = options.denoise == "on";
  settings.sampling.glossy = options.glossy == "on";
  settings.sampling.samples_per_pixel = options.spp;
  settings.sampling.roughness_cutoff = options.roughness_cutoff;
  settings.resolve.exposure = options.exposure;
  settings.resolve.tone_map = render::tone_map_from_name(options.tone_map);
  settings.ray_tracing.backend = options.backend;
  const backends::Backend& backend = backends::find_backend(options.backend);
  if (!backend.structures.empty()) {
    // The default ("sah") means the backend's own default here (optix: optix-fasttrace).
    if (options.accel != "sah" &&
        std::find(backend.structures.begin(), backend.structures.end(), options.accel) == backend.structures.end())
      fail("--accel {} is one of glint's structures; the {} backend takes {}", options.accel, backend.name,
           fmt::join(backend.structures, " or "));
    if (options.accel != "sah") settings.ray_tracing.accel.backend_structure = options.accel;
  } else if (const backends::Backend* owner = backends::structure_owner(options.accel)) {
    fail("--accel {} is a structure of the {} backend: it needs --backend {}", options.accel, owner->name, owner->name);
  } else {
    if (!backend.takes_glint_builders && options.accel != "sah")
      fail("--accel {} applies to the {} backends; the {} backend builds its own structures", options.accel,
           backends::builder_backends_text(), backend.name);
    settings.ray_tracing.accel.set_structure(rt::parse_blas_structure(options.accel));
    if (options.backend == "gl" && settings.ray_tracing.accel.blas == rt::BlasKind::kdtree)
      fail("--accel kdtree applies to the cpu and cuda backends; the gl backend traces BVHs only");
  }
  settings.ray_tracing.update = rt::parse_update_policy(options.update);
  if (render::uses_ray_tracer(settings) && options.deform == "on" && deforms_on_gpu(options)) {
    if (!backends::is_gpu_backend(options.backend) && !is_gl_backend(options))
      fail("--deform-on gpu needs --backend gl, {} when rays are traced (reflections hybrid or rt, shadows rt or "
           "hybrid, or primary rt; the {} backend builds from host vertices); use --deform-on cpu",
           backends::gpu_backends_text(), options.backend);
  }
  settings.validate();
  return settings;
}


void check_structure_follows_deformation(const RenderOptions& options, const render::FramePipelineSettings& settings,
                                         const Scene& scene) {
  // Only a scene that deforms refits: a static one takes every structure with any --update.
  if (options.deform != "on" || scene.deformable_meshes().empty() || !render::uses_ray_tracer(settings)) return;
  if (!backends::find_backend(options.backend).takes_glint_builders) return;
  if (!rt::blas_structure_refittable(settings.ray_tracing.accel.structure()) &&
      settings.ray_tracing.update != rt::UpdatePolicy::rebuild)
    fail("--accel {} cannot be refitted, so --update {} cannot follow the deforming meshes; use --update rebuild "
         "or --deform off",
         options.accel, options.update);
}

namespace {

// A bare OBJ or glTF file has no mirrors (reflectivity 0 without Pm, illum 3..7 or metallic): its
// frames look the same in every --reflections mode, which a user asking for reflections should hear.
void warn_when_nothing_reflects(const RenderOptions& options, const Scene& scene) {
  if (options.reflections == "off") return;
  if (std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.reflectivity > 0.0f; }))
    return;
  log_warning("{}: no material reflects (every reflectivity is 0), so --reflections {} adds nothing; give materials "
              "reflectivity in the MTL (Pm, or illum 3 with Ks), glTF (metallic) or a scene file's \"material\": "
              "{{\"reflectivity\": 0.5}} (docs/scene-format.md)",
              scene.source, options.reflections);
}

}  // namespace

std::vector<int> preview_frames(int frame_count) {
  std::vector<int> frames;
  if (frame_count <= kPreviewFrames) {
    for (int frame = 0; frame < frame_count; ++frame) frames.push_back(frame);
    return frames;
  }
  // Rounded i * (last / (k - 1)): the first and the last frame, the rest evenly between, all distinct
  // (the spacing is at least 1 frame).
  const long long last = frame_count - 1, gaps = kPreviewFrames - 1;
  for (long long i = 0; i < kPreviewFrames; ++i) frames.push_back(static_cast<int>((i * last + gaps / 2) / gaps));
  return frames;
}

namespace {

// Why `text` is not "x,y,z" ("\"<text>\": expected ..."), or empty when it is one, then in `point`.
std::string point_text_problem(std::string_view text, vec3& point) {
  float values[3] = {0.0f, 0.0f, 0.0f};
  int count = 0;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    std::string_view part = text.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin);
    while (!part.empty() && (part.front() == ' ' || part.front() == '\t')) part.remove_prefix(1);
    while (!part.empty() && (part.back() == ' ' || part.back() == '\t')) part.remove_suffix(1);
    float value = 0.0f;
    const auto [stop, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (count == 3 || part.empty() || error != std::errc() || stop != part.data() + part.size() || !std::isfinite(value))
      break;
    values[count++] = value;
    if (comma == std::string_view::npos) {
      if (count != 3) break;
      point = vec3(values[0], values[1], values[2]);
      return {};
    }
    begin = comma + 1;
  }
  return fmt::format("\"{}\": expected x,y,z (three finite numbers separated by commas)", text);
}

}  // namespace

vec3 parse_point_flag(std::string_view flag, std::string_view text) {
  vec3 point(0.0f);
  const std::string problem = point_text_problem(text, point);
  if (!problem.empty()) fail("{} {}", flag, problem);
  return point;
}

bool deforms_on_gpu(const RenderOptions& options) {
  if (!options.deform_on.empty()) return options.deform_on == "gpu";
  // gl follows GPU-posed meshes under every --update: refits in GL compute, and rebuilds (rebuild, or
  // auto past its SAH ratio, measured in GL compute) on the host from the positions read back.
  return backends::is_gpu_backend(options.backend) || is_gl_backend(options);
}

void add_render_command(CLI::App& app, RenderOptions& options) {
  CLI::App* command = app.add_subcommand(
      "render", "Render frames of a scene's walkthrough headless: PNG frames, timings.csv, run.json");
  command->add_option("scene", options.scene, "Preset (atrium, atrium-simple, sponza) or scene file")
      ->capture_default_str();
  command->add_option("--reflections", options.reflections,
                      "Reflections: off (direct light only), ssr (screen space only), hybrid (SSR, rays where it "
                      "failed), rt (rays for every reflective pixel: the reference) or auto (per 8x8 tile: SSR "
                      "only, SSR + rays or rays only, from SSR's failures and measured costs; docs/hybrid.md)")
      ->check(CLI::IsMember(render::kReflectionModeNames.names()))
      ->capture_default_str();
  command->add_option("--backend", options.backend,
                      "Ray tracing backend for hybrid and rt reflections and --shadows rt|hybrid: " +
                          backends::backends_help())
      ->check(CLI::IsMember(backends::backend_names()))
      ->capture_default_str();
  command->add_option("--accel", options.accel,
                      "Structure of the " + backends::builder_backends_text() +
                          " backends' per-mesh BVHs (kdtree: an SAH kd-tree, cpu and cuda only): " + builder_names() +
                          own_structures_help())
      ->check([](const std::string& name) {
        if (backends::structure_owner(name) != nullptr) return std::string();
        try {
          (void)rt::parse_blas_structure(name);
          return std::string();
        } catch (const Error& error) {
          return std::string(error.what());
        }
      })
      ->capture_default_str();
  command->add_option("--update", options.update,
                      "How deforming meshes' structures follow them each frame: rebuild, refit, or auto (refit, "
                      "rebuild once the SAH cost drifted 30 % above the last build's; with --deform-on gpu the "
                      "cost is measured on the GPU and read one or more frames late); --backend gl deforming on "
                      "the GPU refits in GL compute and rebuilds on the host from positions read back (rebuild: "
                      "every frame, slow)")
      ->check(CLI::IsMember(rt::kUpdatePolicyNames.names()))
      ->capture_default_str();
  command->add_option("--width", options.width, "Image width in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  command->add_option("--height", options.height, "Image height in pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  command
      ->add_option("--frames", options.frames,
                   "Frames to render: N, A:B (inclusive), A:B:step, a comma list such as 1800,2100,2300,4400, or all; "
                   "default: a preview of " + std::to_string(kPreviewFrames) +
                       " frames spread evenly from the walkthrough's first to its last")
      ->check([](const std::string& text) {
        return text.find_first_not_of(" \t") == std::string::npos
                   ? std::string("empty value; give N, A:B, A:B:step, a comma list, or all")
                   : std::string();
      });
  const auto point_check = [](const std::string& text) {
    vec3 point(0.0f);
    return point_text_problem(text, point);
  };
  CLI::Option* camera = command->add_option("--camera", options.camera,
                                            "Fixed camera position x,y,z (with --target): every frame is seen from "
                                            "there instead of along the walkthrough's camera path")
                            ->check(point_check);
  CLI::Option* target =
      command->add_option("--target", options.target, "Point x,y,z the --camera looks at")->check(point_check);
  camera->needs(target);
  target->needs(camera);
  add_flat_normals_flag(*command, options.flat_normals);
  command->add_option("--out", options.out,
                      "Output folder (created if missing); a folder holding an earlier run is refused unless "
                      "--overwrite")
      ->capture_default_str();
  command->add_flag("--overwrite", options.overwrite,
                    "Replace the earlier run in --out: its frames, debug views, timings.csv, scopes.csv, run.json and "
                    "video are removed first (other files are kept)");
  command->add_flag("--debug-views", options.debug_views,
                    "Also write albedo, normals, positions, depth, shadow mask, SSR reflection and failure mask per frame");
  command->add_flag("--video", options.video, "Also encode DIR/walkthrough.mp4 with ffmpeg (must be on PATH)");
  command->add_option("--format", options.format,
                      "Image files: png (8-bit sRGB, tone mapped) or exr (linear float RGB before the tone map: "
                      "frames and debug views; docs/render-command.md)")
      ->check(CLI::IsMember({"png", "exr"}))
      ->capture_default_str();
  command->add_flag("--timings-only", options.timings_only,
                    "Write no images, only timings.csv and run.json: frames follow each other without the "
                    "PNG encoding in between, so the GPU stays busy (for measurements)")
      ->excludes("--video")
      ->excludes("--debug-views");
  command->add_flag("--profile-scopes", options.profile_scopes,
                    "Also write scopes.csv: per frame, the GPU time of every pass and of the scopes nested in it "
                    "(frame, scope path such as gbuffer/compute_visibility/tiles, depth, ms); works with "
                    "--timings-only (docs/render-command.md)");
  command->add_option("--deform", options.deform, "Animate the deformable meshes: on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command->add_option("--deform-on", options.deform_on,
                      "Where the deformable meshes are posed: gpu (GL compute writing the GL vertices; CUDA kernels "
                      "the cuda or optix backend's positions, whose structures follow on the GPU; the gl backend's "
                      "positions written by the same GL compute and its structures refitted in GL compute, "
                      "rebuilt on the host from positions read back under --update rebuild, and auto past its "
                      "ratio) or cpu; default: gpu with --backend cuda, optix or gl; else cpu")
      ->check(CLI::IsMember({"gpu", "cpu"}));
  command->add_option("--hold-frame", options.hold_frame,
                      "Hold the scene still at walkthrough frame N: every frame rendered has frame N's camera, "
                      "light and deformed meshes, while the frames (--frames: their numbers, file names, the "
                      "glossy sampling sequence and the denoiser's history) still advance; for flicker on a "
                      "still scene (docs/render-command.md)")
      ->check([](const std::string& text) {
        int frame = -1;
        const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), frame);
        return error == std::errc() && stop == text.data() + text.size() && frame >= 0
                   ? std::string()
                   : "\"" + text + "\": expected a walkthrough frame number (a whole number, 0 or more)";
      });
  command->add_option("--blur-radius", options.blur_radius, "Reflection blur radius in pixels (0 = off)")
      ->check(CLI::Range(0, 32))
      ->capture_default_str();
  command->add_option("--glossy", options.glossy,
                      "Glossy reflections: on (a material's roughness widens its reflection: GGX samples) or off "
                      "(every surface a mirror, the paper's reflections); docs/glossy.md")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command->add_option("--spp", options.spp,
                      "Reflection samples per pixel and frame (the reflection passes run once per sample; "
                      "only the first is timed); 256 with --reflections rt --denoise off is the converged reference")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  command->add_option("--roughness-cutoff", options.roughness_cutoff,
                      "Roughness above which SSR leaves a pixel to the rays (hybrid) or unreflected (ssr)")
      ->check(CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
  command->add_option("--denoise", options.denoise,
                      "Reflection filter: on (temporal accumulation with reprojection + edge-aware spatial filter, "
                      "docs/glossy.md) or off (the paper's Gaussian blur, --blur-radius)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command->add_option("--exposure", options.exposure, "Exposure applied before the tone map")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->add_option("--tone-map", options.tone_map, "Tone map: aces, reinhard or none")
      ->check(CLI::IsMember(render::kToneMapNames.names()))
      ->capture_default_str();
  command->add_option("--shadow-map-size", options.shadow_map_size, "Shadow cube map face size in texels")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  command
      ->add_option("--shadow-cube-draw", options.shadow_cube_draw,
                   "How the shadow cube map's faces are drawn: per-face (six draws) or layered (one draw through a "
                   "geometry shader); same shadows, different speed (docs/perf.md)")
      ->check(CLI::IsMember(render::kShadowCubeDrawNames.names()))
      ->capture_default_str();
  command
      ->add_option("--gbuffer", options.gbuffer,
                   "How the G-buffer is made: raster (one draw that shades every image) or visibility (a draw of "
                   "triangle ids, then a compute pass rebuilds the images); same images (docs/render.md)")
      ->check(CLI::IsMember(render::kGBufferMethodNames.names()))
      ->capture_default_str();
  command
      ->add_option("--primary", options.primary,
                   "With --gbuffer visibility, how the triangle ids are made: raster (the id draw), compute (a "
                   "compute-shader rasteriser: nearly the same ids, much faster where few SMs run fragment "
                   "shaders, as on an H100), auto (compute where a GPU timed it on the first frame at least 1.25x "
                   "faster than raster, else raster; untimed raster on software GL; run.json says which) or rt "
                   "(a camera ray per pixel through the --backend tracer; an experiment); docs/render.md")
      ->check(CLI::IsMember(render::kPrimaryVisibilityNames.names()))
      ->capture_default_str();
  command
      ->add_option("--shadows", options.shadows,
                   "How the light's shadow is made: cube (the cube map, the paper's method), rt (a shadow ray per "
                   "lit pixel through --backend) or hybrid (the cube map at half --shadow-map-size, rays where it is "
                   "uncertain); docs/render.md")
      ->check(CLI::IsMember(render::kShadowMethodNames.names()))
      ->capture_default_str();
  command->add_option("--ssr-max-steps", options.ssr_max_steps, "Most screen-space march steps per pixel")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  command->add_option("--ssr-thickness", options.ssr_thickness,
                      "How far behind a surface an SSR ray still meets it, as a fraction of its view depth (0..1]")
      ->check(CLI::PositiveNumber & CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
  command->add_option("--ssr-confidence", options.ssr_confidence,
                      "Lowest confidence of a trusted SSR hit; below it the pixel fails (0..1)")
      ->check(CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
  auto* ray_budget = command->add_option("--ray-budget", options.ray_budget,
                                         "--reflections auto: most rays traced per frame (fast camera motion "
                                         "lowers it, a still camera restores it)")
                         ->check(CLI::Range(0LL, 0xffffffffLL));
  command->add_option("--reflection-budget", options.reflection_budget_ms,
                      "--reflections auto: milliseconds of reflection work (SSR, ray list, trace, hit shading) "
                      "per frame, turned into rays by the measured costs")
      ->check(CLI::PositiveNumber)
      ->excludes(ray_budget);
  command->add_option("--auto-quality", options.auto_quality,
                      "--reflections auto: largest fraction of a tile's reflective pixels SSR may leave "
                      "unreflected before the tile gets rays (0..1)")
      ->check(CLI::Range(0.0f, 1.0f))
      ->capture_default_str();
}

int run_render_command(const RenderOptions& options) {
  // Under mpirun: this rank's GPU, chosen before any GL or CUDA call (nothing changes with one rank).
  const mpi::RankSession rank;
  const render::FramePipelineSettings settings = render_pipeline_settings(options);
  if (options.video && writes_linear_images(options))
    fail("--video needs --format png: the video is encoded from the 8-bit frames");
  // Checked before the scene is loaded, so that a typo costs no loading time. No --frames: a preview.
  std::optional<FrameSelection> selection;
  if (options.frames == "all") selection = FrameSelection::all();
  else if (!options.frames.empty()) selection = FrameSelection::parse(options.frames);
  std::optional<CameraPathSpec> fixed_camera;
  if (!options.camera.empty() || !options.target.empty()) {
    fixed_camera = CameraPathSpec::fixed(parse_point_flag("--camera", options.camera),
                                         parse_point_flag("--target", options.target));
    if (fixed_camera->points.front() == fixed_camera->targets.front())
      fail("--camera {} and --target {} are the same point: the camera needs a point to look at", options.camera,
           options.target);
  }

  LoadOptions load;
  load.flat_normals = options.flat_normals;
  Scene scene = load_scene(options.scene, load);
  check_structure_follows_deformation(options, settings, scene);
  warn_when_nothing_reflects(options, scene);
  if (fixed_camera) {
    fixed_camera->fov_y_degrees = scene.walkthrough.camera.fov_y_degrees;
    scene.walkthrough.camera = *fixed_camera;
  }
  const WalkthroughAnimation animation(scene);
  const std::vector<int> frames =
      selection ? selection->resolve(animation.frame_count()) : preview_frames(animation.frame_count());
  RenderOptions recorded = options;  // run.json names the frames the run chose
  if (!selection) {
    recorded.frames = fmt::format("{}", fmt::join(frames, ","));
    if (static_cast<int>(frames.size()) < animation.frame_count())
      std::fprintf(stderr,
                   "glint: no --frames: rendering a preview, %zu of the walkthrough's %d frames (%s); "
                   "--frames all renders every frame\n",
                   frames.size(), animation.frame_count(), recorded.frames.c_str());
  }
  // Before anything is written: a CUDA run on a machine without a usable GPU is one clear line.
  if (render::uses_ray_tracer(settings)) {
    backends::check_backend_runnable(options.backend);
  }

  if (mpi::world().size > 1) return mpi::run_render_shared(options, recorded, settings, scene, frames, rank.about());
  const OutputFolder out(options.out, options.overwrite ? EarlierRun::replace : EarlierRun::refuse);
  HeadlessGlContext context;  // logs its renderer with --verbose
  const bool images = !options.timings_only;
  FrameLoopOptions loop_options{options.width, options.height, options.deform == "on", deforms_on_gpu(options)};
  set_image_capture(options, loop_options);  // read back frames later through pixel-pack buffers, no stall
  // Debug views are read from the pipeline's images, which must still hold the frame.
  loop_options.serialized = options.debug_views;
  loop_options.profile_scopes = options.profile_scopes;
  if (options.hold_frame >= 0) loop_options.hold_frame = options.hold_frame;
  FrameLoop loop(scene, settings, loop_options, pass_timing_for_renderer(context.renderer()));
  render::FramePipeline& pipeline = loop.pipeline();

  RenderRunRecord record(recorded, scene, context, loop.pass_timing(), frames);
  if (pipeline.ray_tracer() != nullptr) record.set_ray_tracer(settings.ray_tracing, pipeline.ray_tracer()->stats());
  CsvWriter timings(out.path() / "timings.csv", RenderRunRecord::timings_header());
  std::optional<CsvWriter> scopes;
  if (options.profile_scopes)
    scopes.emplace(out.path() / "scopes.csv", std::vector<std::string>{"frame", "scope", "depth", "ms"});
  std::optional<FfmpegVideoWriter> video;
  if (options.video)
    video.emplace(out.path() / "walkthrough.mp4", options.width, options.height, scene.walkthrough.frames_per_second);
  // PNG and EXR encoding runs beside the loop (a bounded queue), so the GPU is not left idle meanwhile.
  std::optional<ImageWriterThread> image_writer;
  if (images) image_writer.emplace();

  ProgressBar progress("render", frames.size());
  const Stopwatch run_watch;
  // A frame that came back complete: its images go to the writer, its row to timings.csv.
  const auto keep = [&](FrameMeasurement& measured) {
    if (measured.final_image && video) video->add_frame(*measured.final_image);
    if (image_writer) write_frame_image_files(*image_writer, out, options, measured, pipeline);
    timings.add_row(record.add_frame(measured));
    if (scopes)
      for (const ScopeTime& scope : measured.scopes)
        scopes->add_row({measured.frame, scope.path, scope.depth, scope.milliseconds});
    progress.tick();
  };
  // Ctrl-C or SIGTERM: no new frame is started; the frames in flight are finished and written, then
  // timings.csv and run.json are committed with the frames done so far.
  const InterruptionScope interruptible;
  for (const int frame : frames) {
    if (interruption_requested()) break;
    for (FrameMeasurement& measured : loop.submit(frame)) keep(measured);
  }
  for (FrameMeasurement& measured : loop.drain()) keep(measured);
  if (image_writer) image_writer->finish();  // every image on disk (or the first error) before timings.csv
  progress.finish();
  if (video) video->finish();
  timings.commit();
  if (scopes) scopes->commit();
  std::optional<rt::RayTracerStats> tracer_stats;
  if (pipeline.ray_tracer() != nullptr) tracer_stats = pipeline.ray_tracer()->stats();
  if (interruption_requested()) record.mark_interrupted(interruption_signal_name());
  record.set_primary_visibility(pipeline.raster());
  record.write(out.path() / "run.json", run_watch.elapsed_ms(), tracer_stats);
  if (interruption_requested()) {
    log_warning("render: interrupted by {} after {} of {} frames; {} holds them, their timings and run.json",
              interruption_signal_name(), timings.row_count(), frames.size(), out.path().string());
    return interrupted_exit_code();
  }
  log_info("wrote {} frames to {}", frames.size(), out.path().string());
  return 0;
}

}  // namespace glint
