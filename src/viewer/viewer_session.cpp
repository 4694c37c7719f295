#include "viewer/viewer_session.h"

#include "backends/registry.h"
#include "core/error.h"
#include "cuda/device_query.h"
#include "gl/gpu_memory.h"
#include "scene/load_scene.h"
#include "viewer/viewer_settings.h"

#include <utility>

namespace glint::viewer {
namespace {

Scene load(const RenderOptions& options) {
  LoadOptions load_options;
  load_options.flat_normals = options.flat_normals;
  return load_scene(options.scene, load_options);
}

// What run_render_command checks before it writes anything, so a setting this machine cannot run is
// refused when it is chosen rather than when the loop is built.
void check_runnable(const RenderOptions& options) {
  const render::FramePipelineSettings settings = render_pipeline_settings(options);
  if (render::uses_ray_tracer(settings)) {
    backends::check_backend_built(options.backend);
    if (backends::is_gpu_backend(options.backend)) require_cuda_gpu(("backend " + options.backend).c_str());
  }
  if (options.deform == "on" && deforms_on_gpu(options)) require_cuda_gpu("deformation on the GPU");
}

}  // namespace

ViewerSession::ViewerSession(const RenderOptions& options, PassTimingMethod pass_timing)
    : options_(options), pass_timing_(pass_timing), rest_scene_(load(options)) {
  check_runnable(options_);
  animation_ = std::make_unique<WalkthroughAnimation>(working_scene());
}

ViewerSession::~ViewerSession() = default;

void ViewerSession::set_options(const RenderOptions& options) {
  if (same_viewer_settings(options, options_)) return;
  check_runnable(options);
  if (options.scene != options_.scene || options.flat_normals != options_.flat_normals) {
    Scene scene = load(options);
    rest_scene_ = std::move(scene);
  }
  options_ = options;
  animation_ = std::make_unique<WalkthroughAnimation>(working_scene());
  stale_ = true;
}

void ViewerSession::set_fixed_light(std::optional<vec3> position) {
  fixed_light_ = position;
  animation_ = std::make_unique<WalkthroughAnimation>(working_scene());
  stale_ = true;
}

void ViewerSession::reload_scene() {
  Scene scene = load(options_);  // a broken file leaves the scene as it was
  rest_scene_ = std::move(scene);
  animation_ = std::make_unique<WalkthroughAnimation>(working_scene());
  stale_ = true;
}

Scene ViewerSession::working_scene() const {
  Scene scene = rest_scene_;
  if (fixed_light_) {
    scene.walkthrough.light.points = {*fixed_light_};
    scene.light.position = *fixed_light_;
  }
  return scene;
}

FrameLoopOptions ViewerSession::loop_options(const RenderOptions& options) const {
  FrameLoopOptions loop_options{options.width, options.height, options.deform == "on", deforms_on_gpu(options)};
  loop_options.capture_final = true;
  loop_options.serialized = true;  // the debug views are read from the pipeline after each frame
  return loop_options;
}

void ViewerSession::rebuild() {
  free_timer_.reset();
  loop_.reset();  // its GL objects go before the new ones are made
  scene_ = working_scene();
  try {
    loop_ = std::make_unique<FrameLoop>(scene_, render_pipeline_settings(options_), loop_options(options_),
                                        pass_timing_);
  } catch (const Error&) {
    // Back to the settings that last built (the caller shows the error); the next render uses them.
    if (built_options_) options_ = *built_options_;
    throw;
  }
  built_options_ = options_;
  free_timer_ = std::make_unique<GpuTimer>(pass_timing_);
  free_frames_ = 0;
  stale_ = false;
  diverged_ = false;
  posed_frame_.reset();
  last_rebuilt_ = true;
}

FrameMeasurement ViewerSession::render(const ViewPoint& view) {
  if (view.frame < 0 || view.frame >= frame_count())
    fail("frame {} is outside the walkthrough's frames 0 to {}", view.frame, frame_count() - 1);
  last_rebuilt_ = false;
  if (stale_ || (diverged_ && (!view.camera || posed_frame_ != view.frame))) rebuild();
  if (!view.camera || posed_frame_ != view.frame) {
    FrameMeasurement measured = loop_->run(view.frame);
    posed_frame_ = view.frame;
    if (!view.camera) return measured;
  }
  // Free flight: the scene stays posed at the frame, the pipeline renders it from the free camera.
  diverged_ = true;
  FrameState state = animation_->at(view.frame);
  state.camera = *view.camera;
  render::FramePipeline& pipeline = loop_->pipeline();
  free_timer_->begin_frame();
  pipeline.render(state, free_timer_.get());
  free_timer_->end_frame();
  FrameMeasurement measured;
  measured.frame = view.frame;
  measured.times = *free_timer_->take_frame(free_frames_++, /*wait=*/true);
  measured.latency_ms = measured.frame_ms = measured.times.latency_ms;
  if (pipeline.ray_tracer() != nullptr) measured.accel_update_ms = 0.0;  // the scene did not move
  measured.ssr_counts = pipeline.read_counts();
  measured.ray_stats = pipeline.ray_trace_stats();
  measured.gpu_memory_used_bytes = gpu_memory_used_bytes();
  measured.final_image = pipeline.read_final();
  return measured;
}

std::vector<render::DebugView> ViewerSession::debug_views() {
  if (!loop_) return {};
  return loop_->pipeline().read_debug_views();
}

ImageRgba8 ViewerSession::render_reference(const ViewPoint& view) {
  RenderOptions reference = options_;
  reference.reflections = "rt";
  check_runnable(reference);
  Scene scene = working_scene();
  FrameLoop loop(scene, render_pipeline_settings(reference), loop_options(reference), pass_timing_);
  FrameMeasurement measured = loop.run(view.frame);
  if (!view.camera) return std::move(*measured.final_image);
  FrameState state = animation_->at(view.frame);
  state.camera = *view.camera;
  loop.pipeline().render(state);
  return loop.pipeline().read_final();
}

}  // namespace glint::viewer
