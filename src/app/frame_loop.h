#pragma once
// One walkthrough frame as `glint render` and `glint bench` run it: pose the deformable meshes (on
// the CPU, or on the GPU with a GPU deformer), bring the ray tracer's structures up to date, render
// every pass, wait for the GPU, and collect what the frame measured. FrameLoop owns what a run sets
// up once (the deformers, the pipeline, a GPU deformer, the pass timer); the commands decide which
// frames to run and what to write.
//
//   FrameLoop loop(scene, settings, {1280, 720, true, false}, pass_timing_for_renderer(context.renderer()));
//   for (int frame : frames) record(loop.run(frame));
#include "gl/gpu_timer.h"
#include "render/frame_pipeline.h"
#include "render/ray_traced_reflections.h"
#include "render/ssr_pass.h"
#include "scene/camera_path.h"
#include "scene/scene.h"
#include "scene/sine_deformer.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace glint {

namespace cuda {
class GpuSceneDeformer;
}

// What one frame measured.
struct FrameMeasurement {
  int frame = 0;
  FrameTimes times;                                     // GPU passes
  double cpu_frame_ms = 0.0;                            // wall clock of the whole frame
  double deform_ms = 0.0;                               // cpu: deformers + GL vertex upload; gpu: the kernels
  double accel_update_ms = 0.0;                         // the ray tracer's update of deformed meshes
  std::optional<render::SsrCounts> ssr_counts;          // with SSR
  std::optional<render::RayTraceFrameStats> ray_stats;  // with ray tracing
  // Sampled after the frame, for long-run checks (docs/reliability.md): the process's resident memory
  // and the GPU's memory in use (NVIDIA drivers only, see gl/gpu_memory.h).
  std::optional<std::uint64_t> resident_bytes;
  std::optional<std::uint64_t> gpu_memory_used_bytes;
};

struct FrameLoopOptions {
  int width = 1280;
  int height = 720;
  bool deform = true;          // animate the scene's deformable meshes (when it has any)
  bool deform_on_gpu = false;  // with CUDA kernels (needs a CUDA GPU; see render/gpu_deformation.h)
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

  // Renders walkthrough frame `frame` (deform, update, render, glFinish) and returns what it
  // measured. The final image stays in the pipeline (pipeline().read_final()).
  FrameMeasurement run(int frame);

  render::FramePipeline& pipeline() { return pipeline_; }
  const WalkthroughAnimation& animation() const { return animation_; }
  PassTimingMethod pass_timing() const { return timer_.method(); }
  bool deforms() const { return deformers_.has_value(); }

private:
  struct DeformTimes {
    double deform_ms = 0.0;
    double accel_update_ms = 0.0;
  };
  DeformTimes deform(int frame);

  Scene* scene_;
  WalkthroughAnimation animation_;
  std::optional<SceneDeformers> deformers_;
  render::FramePipeline pipeline_;
  std::unique_ptr<cuda::GpuSceneDeformer> gpu_deformer_;
  GpuTimer timer_;
};

}  // namespace glint
