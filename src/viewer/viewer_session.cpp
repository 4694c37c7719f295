#include "viewer/viewer_session.h"

#include "backends/registry.h"
#include "core/error.h"
#include "cuda/device_query.h"
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
    backends::check_backend_runnable(options.backend);
  }
  // CUDA poses only a cuda or optix tracer's positions; GL poses its vertex buffer and the gl backend's.
  if (options.deform == "on" && deforms_on_gpu(options) && render::uses_ray_tracer(settings) &&
      backends::is_gpu_backend(options.backend))
    require_cuda_gpu("deformation on the GPU");
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
  // No readback of every frame: the viewer shows the pipeline's texture and reads the final image
  // (and the debug views) from the pipeline only when asked, which serialized keeps possible.
  loop_options.serialized = true;
  return loop_options;
}

void ViewerSession::rebuild() {
  loop_.reset();  // its GL objects go before the new ones are made
  scene_ = working_scene();
  try {
    const render::FramePipelineSettings settings = render_pipeline_settings(options_);
    check_structure_follows_deformation(options_, settings, scene_);
    loop_ = std::make_unique<FrameLoop>(scene_, settings, loop_options(options_), pass_timing_);
  } catch (const Error&) {
    // Back to the settings that last built (the caller shows the error); the next render uses them.
    if (built_options_) options_ = *built_options_;
    throw;
  }
  built_options_ = options_;
  stale_ = false;
  last_rebuilt_ = true;
}

FrameMeasurement ViewerSession::render(const ViewPoint& view) {
  if (view.frame < 0 || view.frame >= frame_count())
    fail("frame {} is outside the walkthrough's frames 0 to {}", view.frame, frame_count() - 1);
  last_rebuilt_ = false;
  if (stale_) rebuild();
  return loop_->run(view.frame, view.camera);
}

GLuint ViewerSession::final_texture() const { return loop_ ? loop_->pipeline().final_texture() : 0; }
int ViewerSession::rendered_width() const { return loop_ ? loop_->pipeline().width() : 0; }
int ViewerSession::rendered_height() const { return loop_ ? loop_->pipeline().height() : 0; }

ImageRgba8 ViewerSession::final_image() const {
  if (!loop_) fail("view: nothing rendered yet");
  return loop_->pipeline().read_final();
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
  (void)loop.run(view.frame, view.camera);
  return loop.pipeline().read_final();
}

}  // namespace glint::viewer
