#pragma once
// --deform-on gpu: the scene's sine deformers run on the GPU, on both sides of the frame and with no
// hand-over between them: GL compute passes pose the frame pipeline's vertex buffer
// (GlSceneDeformer), and with a CUDA ray tracer (cuda, optix) CUDA kernels pose its device positions
// on the tracer's stream (cuda::GpuSceneDeformer, which the structure update and the traces follow on
// that stream). Both evaluate the same formulas (scene/sine_deform_math.h). The gl backend's
// structures live in the same GL context, so GL's pose dispatch also writes its vertex buffer
// (GlTracing::gl_positions, GlSceneDeformer::write_positions_to): one pose for both, no second
// deformer and no copy.
#include "cuda/gpu_scene_deformer.h"
#include "render/frame_pipeline.h"
#include "render/gl_scene_deformer.h"
#include "scene/sine_deformer.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace glint::render {

class GpuDeformation {
public:
  // `deformers` and `pipeline` must outlive this. glint::Error without a CUDA GPU where the pipeline
  // has a CUDA ray tracer, or when it traces rays with a CPU backend (its structures are built from
  // host vertices, which neither deformer touches).
  GpuDeformation(const SceneDeformers& deformers, FramePipeline& pipeline);
  ~GpuDeformation();

  // Poses every deformable mesh for walkthrough frame `frame` on both sides (enqueued, nothing
  // waits; with the gl backend GL's deformer also writes the poses into the tracer's positions) and
  // returns their indices: the dirty list for the structure update.
  std::vector<std::uint32_t> apply(int frame);

  // The CUDA kernels' span of the last apply(), read with cuda_apply_ms(); nullopt without a GPU ray
  // tracer (then only GL deforms, timed by its "deform" scope).
  std::optional<std::uint64_t> last_cuda_apply() const;
  std::optional<double> cuda_apply_ms(std::uint64_t ticket, bool wait);

private:
  // Points GL's deformer at the gl backend's positions (GlSceneDeformer::write_positions_to).
  void target_tracer_positions();

  GlSceneDeformer gl_;
  std::unique_ptr<cuda::GpuSceneDeformer> cuda_;  // null without a CUDA ray tracer
  rt::GlTracing* gl_tracer_ = nullptr;            // the gl backend's GL side, or null
  std::vector<std::uint32_t> tracer_first_vertex_;  // per deforming mesh, target_tracer_positions()'s
};

}  // namespace glint::render
