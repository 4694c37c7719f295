#include "app/frame_loop.h"

#include "core/error.h"
#include "core/process_memory.h"
#include "core/stopwatch.h"
#include "gl/gpu_memory.h"
#include "render/gpu_deformation.h"

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace glint {
namespace {

using Clock = std::chrono::steady_clock;

std::optional<SceneDeformers> make_deformers(const Scene& scene, const FrameLoopOptions& options) {
  if (!options.deform || scene.deformable_meshes().empty()) return std::nullopt;
  return std::optional<SceneDeformers>(std::in_place, scene);
}

// Whether the GPU passed `fence`; waits for it (a minute at most) when `wait`.
bool fence_passed(GLsync fence, bool wait, int frame) {
  const auto give_up = Clock::now() + std::chrono::minutes(1);
  while (true) {
    // The flush bit makes sure the fence reaches the GPU; a timeout of 0 only asks.
    const GLenum status = glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, wait ? 100'000'000 : 0);
    if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED) return true;
    if (status == GL_WAIT_FAILED) fail("frame {}: waiting for the GPU failed (glClientWaitSync)", frame);
    if (!wait) return false;
    if (Clock::now() > give_up) fail("frame {}: the GPU did not finish the frame within a minute", frame);
  }
}

}  // namespace

FrameLoop::FrameLoop(Scene& scene, const render::FramePipelineSettings& settings, const FrameLoopOptions& options,
                     PassTimingMethod pass_timing)
    : scene_(&scene),
      animation_(scene),
      deformers_(make_deformers(scene, options)),
      pipeline_(scene, options.width, options.height, settings),
      timer_(pass_timing),
      serialized_(options.serialized),
      keep_in_flight_(std::min(options.keep_in_flight, kFramesInFlight - 1)) {
  if (deformers_ && options.deform_on_gpu) gpu_deformer_ = std::make_unique<render::GpuDeformation>(*deformers_, pipeline_);
  pipeline_.set_final_capture(options.capture_final);
  pipeline_.set_linear_capture(options.capture_linear);
  if (options.profile_scopes) profiler_.emplace(pass_timing);
  set_hold_frame(options.hold_frame);
}

void FrameLoop::set_hold_frame(std::optional<int> frame) {
  if (frame && (*frame < 0 || *frame >= animation_.frame_count()))
    fail("--hold-frame {}: the walkthrough has {} frames (0 to {})", *frame, animation_.frame_count(),
         animation_.frame_count() - 1);
  hold_frame_ = frame;
}

FrameLoop::~FrameLoop() {
  for (InFlight& frame : in_flight_)
    if (frame.done != nullptr) glDeleteSync(frame.done);
}

// On the CPU the new vertices are copied to GL and the tracer; on the GPU GL and CUDA pose their own
// copies, nothing is copied, and the CUDA kernels' time is read when the frame is done
// (read_cuda_times; GL's deformation is timed by its "deform" scope, --profile-scopes).
FrameLoop::DeformTimes FrameLoop::deform(int frame) {
  if (!deformers_) return {};
  DeformTimes times;
  if (gpu_deformer_) {
    const std::vector<std::uint32_t> dirty = gpu_deformer_->apply(frame);
    times.deform_ticket = gpu_deformer_->last_cuda_apply();
    times.accel_update_ms = pipeline_.update_ray_tracer_on_device(dirty);
    if (rt::DeviceTracing* device = pipeline_.device_tracing()) times.update_ticket = device->last_update();
    return times;
  }
  const Stopwatch watch;
  const std::vector<std::uint32_t> dirty = deformers_->apply(*scene_, frame);
  pipeline_.upload_meshes(dirty);
  times.deform_ms = watch.elapsed_ms();
  times.accel_update_ms = pipeline_.update_ray_tracer(dirty);
  // A GPU backend's update only enqueues work: its GPU time is reported instead.
  if (rt::DeviceTracing* device = pipeline_.device_tracing()) times.update_ticket = device->last_update();
  return times;
}

void FrameLoop::read_cuda_times(DeformTimes& times) {
  // The frame's fence passed. Its GL work came after its CUDA work wherever the frame traced rays on
  // the tracer's stream (the deformer and the update come before the traces there), so nothing waits
  // then; a frame without a CUDA trace may wait here for the deformer's and the update's kernels.
  // Each time is read once (the read frees its timing; the tickets are dropped).
  if (times.deform_ticket) times.deform_ms = gpu_deformer_->cuda_apply_ms(*times.deform_ticket, /*wait=*/true).value();
  if (times.update_ticket)
    times.accel_update_ms = pipeline_.device_tracing()->gpu_ms(*times.update_ticket, /*wait=*/true).value();
  times.deform_ticket.reset();
  times.update_ticket.reset();
}

std::vector<FrameMeasurement> FrameLoop::submit(int frame, const std::optional<CameraState>& camera) {
  std::vector<FrameMeasurement> done;
  // Frames already finished, then (all slots in use) the oldest, however long it takes.
  while (in_flight_.size() > keep_in_flight_)
    if (std::optional<FrameMeasurement> finished = complete_oldest(false)) done.push_back(std::move(*finished));
    else break;
  while (in_flight_.size() >= kFramesInFlight) done.push_back(*complete_oldest(true));

  InFlight submitted{frame, submitted_++, {}, nullptr};
  timer_.begin_frame();  // the frame's latency starts here, before the deformation
  if (profiler_) profiler_->begin_frame();
  // Held: posed (meshes, camera, light) at the held frame, numbered (sampling, history) as submitted.
  const int posed = hold_frame_.value_or(frame);
  submitted.deform = deform(posed);
  FrameState state = animation_.at(posed);
  state.frame = frame;
  if (camera) state.camera = *camera;
  pipeline_.render(state, &timer_);
  if (profiler_) profiler_->end_frame();
  timer_.end_frame();
  submitted.done = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (submitted.done == nullptr) fail("frame {}: glFenceSync failed", frame);
  glFlush();  // hand the frame to the GPU now, so it runs while the CPU prepares the next one
  in_flight_.push_back(submitted);

  if (serialized_) {
    for (FrameMeasurement& finished : drain()) done.push_back(std::move(finished));
    return done;
  }
  while (in_flight_.size() > keep_in_flight_)
    if (std::optional<FrameMeasurement> finished = complete_oldest(false)) done.push_back(std::move(*finished));
    else break;
  return done;
}

std::vector<FrameMeasurement> FrameLoop::drain() {
  std::vector<FrameMeasurement> done;
  while (!in_flight_.empty()) done.push_back(*complete_oldest(true));
  return done;
}

FrameMeasurement FrameLoop::run(int frame, const std::optional<CameraState>& camera) {
  std::vector<FrameMeasurement> done = submit(frame, camera);
  for (FrameMeasurement& finished : drain()) done.push_back(std::move(finished));
  if (done.empty() || done.back().frame != frame) fail("frame {}: the loop did not return it", frame);
  return std::move(done.back());
}

std::optional<FrameMeasurement> FrameLoop::complete_oldest(bool wait) {
  if (in_flight_.empty()) return std::nullopt;
  InFlight& oldest = in_flight_.front();
  if (!fence_passed(oldest.done, wait, oldest.frame)) return std::nullopt;
  // The GPU finished the frame: its queries and readback copies are there, so nothing below waits
  // long (the queries' results may still take a moment to be reported).
  read_cuda_times(oldest.deform);
  std::optional<FrameTimes> times = timer_.take_frame(oldest.index, /*wait=*/true);
  std::optional<render::FrameReadback> readback = pipeline_.take_readback(oldest.index, /*wait=*/true);
  FrameMeasurement measured;
  measured.frame = oldest.frame;
  measured.latency_ms = times->latency_ms;
  measured.frame_ms = last_completed_at_ms_ ? times->completed_at_ms - *last_completed_at_ms_ : times->latency_ms;
  last_completed_at_ms_ = times->completed_at_ms;
  measured.times = std::move(*times);
  measured.deform_ms = oldest.deform.deform_ms;
  if (pipeline_.ray_tracer() != nullptr) measured.accel_update_ms = oldest.deform.accel_update_ms;
  measured.ssr_counts = readback->ssr_counts;
  measured.ray_stats = readback->ray_stats;
  // The gl backend traces in a GL pass of its own: its time is the trace's.
  if (measured.ray_stats)
    for (const PassTime& pass : measured.times.passes)
      if (pass.name == "trace") measured.ray_stats->trace_ms = pass.milliseconds;
  measured.adaptive = readback->adaptive;
  readback->ray_stats = measured.ray_stats;  // with the gl backend's trace time
  pipeline_.observe(measured.times, *readback);  // --reflections auto's cost model
  measured.final_image = std::move(readback->final_image);
  measured.linear_image = std::move(readback->linear_image);
  if (profiler_) measured.scopes = std::move(profiler_->take_frame(oldest.index, /*wait=*/true)->scopes);
  measured.resident_bytes = resident_memory_bytes();
  measured.gpu_memory_used_bytes = gpu_memory_used_bytes();
  glDeleteSync(oldest.done);
  in_flight_.pop_front();
  return measured;
}

}  // namespace glint
