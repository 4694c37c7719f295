#pragma once
// What `glint view` renders, through the same FrameLoop as `glint render`: the scene (kept at rest,
// copied for every rebuild so the deformers start from the rest pose), the settings, and the loop
// built from them on the current GL context (the window's). A settings change rebuilds the loop at
// the next frame; a view is FrameLoop::run(frame, camera), serialized so the final image and the
// debug views can be read from the pipeline after it.
//
// Free flight is the same loop with the flown camera (FrameLoop::submit's camera): the scene is
// posed, the structures updated and the light placed at the view's frame, so the walkthrough's
// clock (playback, deformation, the light) keeps running while the camera is the flown one.
#include "app/frame_loop.h"
#include "app/render_command.h"
#include "core/image.h"
#include "gl/gpu_timer.h"
#include "render/frame_pipeline.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <epoxy/gl.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace glint::viewer {

// Which picture to make: a walkthrough frame, optionally from a free camera instead of the path's.
struct ViewPoint {
  int frame = 0;
  std::optional<CameraState> camera;
  bool operator==(const ViewPoint& other) const {
    return frame == other.frame && camera.has_value() == other.camera.has_value() &&
           (!camera || (camera->position == other.camera->position && camera->target == other.camera->target));
  }
};

class ViewerSession {
public:
  // Loads options.scene and checks the settings (glint::Error: the CLI's one-line messages). The
  // loop is built at the first render.
  ViewerSession(const RenderOptions& options, PassTimingMethod pass_timing);
  ~ViewerSession();

  const RenderOptions& options() const { return options_; }
  // Checks `options` (render_pipeline_settings and the backend's availability) and keeps them; the
  // next render rebuilds the loop when they differ. glint::Error, nothing changed, when they cannot run.
  void set_options(const RenderOptions& options);
  // The light stays at `position` (nullopt: it follows its path again); rebuilds at the next render.
  void set_fixed_light(std::optional<vec3> position);
  const std::optional<vec3>& fixed_light() const { return fixed_light_; }
  // Loads the scene file (or preset) again, keeping settings; the next render rebuilds.
  void reload_scene();

  const Scene& rest_scene() const { return rest_scene_; }
  int frame_count() const { return animation_->frame_count(); }
  // The walkthrough's state at `frame` (with the fixed light when there is one).
  FrameState walkthrough_state(int frame) const { return animation_->at(frame); }

  // Renders `view` and returns what it measured (no final image: the loop leaves it in the pipeline,
  // final_texture() shows it and final_image() reads it). glint::Error for a frame outside the
  // walkthrough.
  FrameMeasurement render(const ViewPoint& view);
  // The last render's final image on the GPU (kFinalFormat, bottom row first; FramePipeline::
  // final_texture) and its size: valid until the next render or rebuild. 0 before the first render.
  GLuint final_texture() const;
  int rendered_width() const;
  int rendered_height() const;
  // The last render's final image read to the host (screenshots, the difference). Waits for the GPU.
  ImageRgba8 final_image() const;
  // The debug views of the last render (see FramePipeline::read_debug_views).
  std::vector<render::DebugView> debug_views();
  // The same view with rt reflections (the reference), rendered by a loop of its own that lives only
  // for this call.
  ImageRgba8 render_reference(const ViewPoint& view);
  // Whether the last render built the loop anew (for the status line).
  bool last_render_rebuilt() const { return last_rebuilt_; }

private:
  Scene working_scene() const;  // the rest scene, its light fixed when asked
  FrameLoopOptions loop_options(const RenderOptions& options) const;
  void rebuild();

  RenderOptions options_;
  std::optional<RenderOptions> built_options_;  // the settings the loop was last built with
  PassTimingMethod pass_timing_;
  Scene rest_scene_;
  Scene scene_;  // what the loop poses in place
  std::optional<vec3> fixed_light_;
  std::unique_ptr<WalkthroughAnimation> animation_;
  std::unique_ptr<FrameLoop> loop_;
  bool stale_ = true;  // settings, light or scene changed since the loop was built
  bool last_rebuilt_ = false;
};

}  // namespace glint::viewer
