#pragma once
// The walkthrough frames as `glint render` and `glint bench` run them: pose the deformable meshes
// (on the CPU, or on the GPU with a GPU deformer), bring the ray tracer's structures up to date,
// render every pass, and collect what each frame measured. FrameLoop owns what a run sets up once
// (the deformers, the pipeline, a GPU deformer, the pass timer); the commands decide which frames
// to run and what to write.
//
// The loop is pipelined: submit(frame) issues a frame and returns without waiting for the GPU;
// what a frame measured (pass times, counters, CUDA times, its final image) is read kFramesInFlight
// frames later at most, from rings of queries and readback slots, once a fence says the GPU has
// finished that frame; only when all slots are in use does submit() wait for the oldest frame.
// Frames come back complete and in order, each exactly once; drain() returns the rest.
//
//   FrameLoop loop(scene, settings, {1280, 720}, pass_timing_for_renderer(context.renderer()));
//   for (int frame : frames)
//     for (FrameMeasurement& done : loop.submit(frame)) record(done);
//   for (FrameMeasurement& done : loop.drain()) record(done);
#include "core/image.h"
#include "gl/gpu_timer.h"
#include "gl/scope_profiler.h"
#include "render/frame_pipeline.h"
#include "render/ray_traced_reflections.h"
#include "render/ssr_pass.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "scene/sine_deformer.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace glint {

namespace render {
class GpuDeformation;
}

// What one frame measured.
struct FrameMeasurement {
  int frame = 0;
  FrameTimes times;            // GPU passes
  // Steady state: the time from the previous frame's completion on the GPU to this one's (the frame
  // rate a run sustains; the first frame of a loop: its latency).
  double frame_ms = 0.0;
  // Latency: from the start of this frame's CPU work (deformation first) to the GPU finishing it.
  double latency_ms = 0.0;
  double deform_ms = 0.0;                               // cpu: deformers + GL vertex upload; gpu: the kernels
  // The ray tracer's update of deformed meshes; absent without a ray tracer (one exists when
  // reflections, shadows or primary visibility trace rays).
  std::optional<double> accel_update_ms;
  std::optional<render::SsrCounts> ssr_counts;          // with SSR
  std::optional<render::RayTraceFrameStats> ray_stats;  // with ray tracing
  std::optional<render::AdaptiveFrameStats> adaptive;   // --reflections auto: its tiles and budget
  // Sampled when the frame's results were read, for long-run checks (docs/reliability.md): the
  // process's resident memory and the GPU's memory in use (NVIDIA drivers only, gl/gpu_memory.h).
  std::optional<std::uint64_t> resident_bytes;
  std::optional<std::uint64_t> gpu_memory_used_bytes;
  std::optional<ImageRgba8> final_image;  // with FrameLoopOptions::capture_final
  std::optional<ImageRgbaF> linear_image;  // with FrameLoopOptions::capture_linear
  // With FrameLoopOptions::profile_scopes: the GPU time of every pass and GlPassScope, nested, in
  // tree order (gl/scope_profiler.h); empty otherwise.
  std::vector<ScopeTime> scopes;
};

struct FrameLoopOptions {
  int width = 1280;
  int height = 720;
  bool deform = true;          // animate the scene's deformable meshes (when it has any)
  bool deform_on_gpu = false;  // GL compute and CUDA kernels (needs a CUDA GPU; see render/gpu_deformation.h)
  // Read every frame's final image back (a pixel-pack buffer per frame in flight, no stall) into
  // FrameMeasurement::final_image.
  bool capture_final = false;
  // Read every frame's linear colour (the tone map's input, FramePipeline::set_linear_capture) back
  // into FrameMeasurement::linear_image, the same way (`glint render --format exr`).
  bool capture_linear = false;
  // Wait for each frame before the next starts (submit() returns exactly the frame it submitted),
  // as the loop did before it was pipelined: for comparisons, and for reading a frame's other
  // images (debug views) from the pipeline right after it.
  bool serialized = false;
  // submit() returns a frame only once this many later frames were submitted (at most
  // kFramesInFlight - 1), as when the GPU runs that far behind: tests use it to read every frame's
  // results frames late on any machine. drain() still returns everything.
  std::size_t keep_in_flight = 0;
  // Time every GlPassScope of each frame, nested (FrameMeasurement::scopes; gl/scope_profiler.h).
  bool profile_scopes = false;
  // `glint render --hold-frame N`: every frame is posed at walkthrough frame N (its camera, its light
  // and its deformed meshes, re-posed each frame as usual) while the frame submitted keeps counting:
  // FrameState::frame, the glossy sampling sequence and the denoiser's history advance, so a still
  // scene shows only what changes frame to frame (flicker). nullopt: frames are posed as numbered.
  std::optional<int> hold_frame = std::nullopt;
};

class FrameLoop {
public:
  // Builds the pipeline (and, in hybrid and rt modes, the ray tracer's structures) on the current GL
  // context. `scene` must outlive the loop; its deformable meshes are posed in place. glint::Error
  // when a GPU deformer is asked for without a CUDA GPU.
  FrameLoop(Scene& scene, const render::FramePipelineSettings& settings, const FrameLoopOptions& options,
            PassTimingMethod pass_timing);
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  // Issues walkthrough frame `frame` (deform, update, render) and returns the frames that finished
  // since the last call, oldest first (serialized: exactly this one). Waits only for the oldest
  // frame in flight when kFramesInFlight are. With `camera` the frame is seen from there instead of
  // the path's camera; everything else (deformation, structure update, light) is still frame
  // `frame`'s: the viewer's free flight, which keeps the walkthrough's clock running.
  std::vector<FrameMeasurement> submit(int frame, const std::optional<CameraState>& camera = std::nullopt);
  // Waits for every frame in flight and returns them, oldest first.
  std::vector<FrameMeasurement> drain();
  // submit() and drain(): this frame, complete; its final image stays in the pipeline
  // (pipeline().read_final()). For warm-up frames, quality images and tests.
  FrameMeasurement run(int frame, const std::optional<CameraState>& camera = std::nullopt);
  std::size_t frames_in_flight() const { return in_flight_.size(); }

  render::FramePipeline& pipeline() { return pipeline_; }
  const WalkthroughAnimation& animation() const { return animation_; }
  // FrameLoopOptions::hold_frame from the next submit on; glint::Error for a frame outside the walkthrough.
  void set_hold_frame(std::optional<int> frame);
  std::optional<int> hold_frame() const { return hold_frame_; }
  PassTimingMethod pass_timing() const { return timer_.method(); }
  bool deforms() const { return deformers_.has_value(); }

private:
  struct DeformTimes {
    double deform_ms = 0.0;
    double accel_update_ms = 0.0;
    // GPU work whose times replace the two above once the frame is done (read_cuda_times): the GPU
    // deformer's kernels, a GPU backend's structure update.
    std::optional<std::uint64_t> deform_ticket;
    std::optional<rt::GpuTicket> update_ticket;
  };
  // A frame submitted and not yet returned.
  struct InFlight {
    int frame = 0;
    std::uint64_t index = 0;  // its number in the timer and the pipeline (0, 1, ... per submit)
    DeformTimes deform;
    GLsync done = nullptr;            // signalled when the GPU finished the frame
  };
  DeformTimes deform(int frame);
  // Replaces a done frame's deform and update times by their GPU times, where tickets say so.
  void read_cuda_times(DeformTimes& times);
  // The oldest frame in flight, when it is finished or `wait`; nullopt otherwise.
  std::optional<FrameMeasurement> complete_oldest(bool wait);

  Scene* scene_;
  WalkthroughAnimation animation_;
  std::optional<SceneDeformers> deformers_;
  render::FramePipeline pipeline_;
  std::unique_ptr<render::GpuDeformation> gpu_deformer_;
  GpuTimer timer_;
  std::optional<ScopeProfiler> profiler_;  // with FrameLoopOptions::profile_scopes
  bool serialized_ = false;
  std::size_t keep_in_flight_ = 0;
  std::optional<int> hold_frame_;
  std::deque<InFlight> in_flight_;
  std::uint64_t submitted_ = 0;
  std::optional<double> last_completed_at_ms_;  // the previous frame's completion (timer's clock)
};

}  // namespace glint
