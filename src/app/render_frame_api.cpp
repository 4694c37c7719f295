#include "app/render_frame_api.h"

#include "app/frame_loop.h"
#include "app/frame_selection.h"
#include "backends/registry.h"
#include "core/error.h"
#include "gl/egl_context.h"
#include "gl/gpu_timer.h"
#include "rt/ray_tracer.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"

#include <string>
#include <vector>

namespace glint {

ImageRgba8 render_frame(const RenderOptions& options, int frame) {
  // The CLI's ranges for --width and --height (add_render_command).
  if (options.width < 1 || options.width > 16384 || options.height < 1 || options.height > 16384)
    fail("render: width and height must be 1 to 16384 pixels, got {}x{}", options.width, options.height);
  if (!options.camera.empty() || !options.target.empty())
    fail("render: a fixed camera is only in `glint render --camera --target`; this renders the walkthrough's");
  const render::FramePipelineSettings settings = render_pipeline_settings(options);
  const FrameSelection selection = FrameSelection::parse(std::to_string(frame));

  LoadOptions load;
  load.flat_normals = options.flat_normals;
  Scene scene = load_scene(options.scene, load);
  const std::vector<int> frames = selection.resolve(WalkthroughAnimation(scene).frame_count());
  check_structure_follows_deformation(options, settings, scene);
  if (render::uses_ray_tracer(settings)) {
    backends::check_backend_runnable(options.backend);
  }

  HeadlessGlContext context;
  FrameLoopOptions loop_options{options.width, options.height, options.deform == "on", deforms_on_gpu(options)};
  loop_options.capture_final = true;
  FrameLoop loop(scene, settings, loop_options, pass_timing_for_renderer(context.renderer()));
  std::vector<FrameMeasurement> done = loop.submit(frames.front());
  for (FrameMeasurement& measured : loop.drain()) done.push_back(std::move(measured));
  if (done.size() != 1 || !done.front().final_image)
    fail("render: frame {} came back without its image", frame);  // FrameLoop's contract says it cannot
  return std::move(*done.front().final_image);
}

}  // namespace glint
