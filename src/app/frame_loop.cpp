#include "app/frame_loop.h"

#include "core/error.h"
#include "core/process_memory.h"
#include "cuda/device_query.h"
#include "gl/gpu_memory.h"
#include "render/gpu_deformation.h"

#include <epoxy/gl.h>

#include <chrono>
#include <utility>
#include <vector>

namespace glint {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::optional<SceneDeformers> make_deformers(const Scene& scene, const FrameLoopOptions& options) {
  if (!options.deform || scene.deformable_meshes().empty()) return std::nullopt;
  if (options.deform_on_gpu) require_cuda_gpu("--deform-on gpu");
  return std::optional<SceneDeformers>(std::in_place, scene);
}

}  // namespace

FrameLoop::FrameLoop(Scene& scene, const render::FramePipelineSettings& settings, const FrameLoopOptions& options,
                     PassTimingMethod pass_timing)
    : scene_(&scene),
      animation_(scene),
      deformers_(make_deformers(scene, options)),
      pipeline_(scene, options.width, options.height, settings),
      timer_(pass_timing) {
  if (deformers_ && options.deform_on_gpu) gpu_deformer_ = render::make_gpu_deformer(*deformers_, pipeline_);
}

FrameLoop::~FrameLoop() = default;

// On the CPU the new vertices are copied to GL and the tracer; with a GPU deformer nothing is copied
// and the kernels' time is read after the frame (last_apply_ms).
FrameLoop::DeformTimes FrameLoop::deform(int frame) {
  if (!deformers_) return {};
  DeformTimes times;
  if (gpu_deformer_) {
    const std::vector<std::uint32_t> dirty = gpu_deformer_->apply(frame);
    times.accel_update_ms = pipeline_.update_ray_tracer_on_device(dirty);
    return times;
  }
  const auto start = Clock::now();
  const std::vector<std::uint32_t> dirty = deformers_->apply(*scene_, frame);
  pipeline_.upload_meshes(dirty);
  times.deform_ms = milliseconds_since(start);
  times.accel_update_ms = pipeline_.update_ray_tracer(dirty);
  return times;
}

FrameMeasurement FrameLoop::run(int frame) {
  const auto frame_start = Clock::now();
  DeformTimes deform_times = deform(frame);
  timer_.begin_frame();
  pipeline_.render(animation_.at(frame), &timer_);
  timer_.end_frame();
  glFinish();  // the CPU frame time includes the GPU finishing the frame
  const double cpu_frame_ms = milliseconds_since(frame_start);
  if (gpu_deformer_) deform_times.deform_ms = gpu_deformer_->last_apply_ms();
  // A GPU backend's update only enqueues work: report its GPU time instead.
  if (rt::DeviceTracing* device = pipeline_.device_tracing(); device && deformers_)
    if (const std::optional<double> update_ms = device->last_update_ms()) deform_times.accel_update_ms = *update_ms;

  timer_.wait_for_all();
  std::vector<FrameTimes> completed = timer_.take_completed();
  if (completed.size() != 1) fail("frame {}: the pass timer returned {} frames' timings, expected 1", frame, completed.size());
  return {frame,
          std::move(completed.front()),
          cpu_frame_ms,
          deform_times.deform_ms,
          deform_times.accel_update_ms,
          pipeline_.read_counts(),
          pipeline_.ray_trace_stats(),
          resident_memory_bytes(),
          gpu_memory_used_bytes()};
}

}  // namespace glint
