#pragma once
// The paper's sine deformer in CUDA (--deform-on gpu, with a GPU ray tracer): every deformable mesh is
// posed by CUDA kernels from its rest pose into the ray tracer's own copy of the positions, on the
// tracer's stream, so a deforming frame moves no vertex through the host and its structure update
// and traces follow on that stream. GL poses its vertex buffer itself (render/gl_scene_deformer.h):
// no GL buffer is shared, so deforming adds no GL-CUDA hand-over. The formulas and the normal
// gathering are the CPU deformer's (scene/sine_deform_math.h, SineDeformer's vertex -> triangle
// adjacency). Plain C++ (no CUDA headers); a build without CUDA throws at construction.
#include "rt/ray_tracer.h"
#include "scene/scene.h"
#include "scene/sine_deformer.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace glint::cuda {

class GpuSceneDeformer {
public:
  // `deformers`: the CPU deformers of the scene (their rest poses, parameters and adjacency are
  // uploaded once). `tracer`: the GPU ray tracer whose device_positions() are rewritten; the work
  // runs on its stream, so its update sees the new positions. Needs a CUDA GPU; glint::Error otherwise.
  GpuSceneDeformer(const SceneDeformers& deformers, rt::DeviceTracing& tracer);
  ~GpuSceneDeformer();
  GpuSceneDeformer(const GpuSceneDeformer&) = delete;
  GpuSceneDeformer& operator=(const GpuSceneDeformer&) = delete;

  // Enqueues the pose of every deformable mesh at `frame` (the CPU deformer's time) and returns the
  // meshes it changed, ascending. Returns before the GPU is done.
  std::vector<std::uint32_t> apply(int frame);
  // The ticket of the last apply()'s kernels, for apply_ms; glint::Error before the first apply().
  std::uint64_t last_apply() const;
  // GPU time of that apply's kernels in milliseconds (cuda/gpu_span_pool.h: read frames later, once
  // done; nullopt while not done and not `wait`). Each apply's time is read once: its span is kept
  // until then, and freed by the read.
  std::optional<double> apply_ms(std::uint64_t ticket, bool wait);

private:
  struct State;
  std::unique_ptr<State> state_;
};

// One mesh posed on the GPU and read back (for tests): positions and unit normals at `time_seconds`.
struct GpuPosedMesh {
  std::vector<vec3> positions;
  std::vector<vec3> normals;
};
GpuPosedMesh pose_mesh_on_gpu(const SineDeformer& deformer, float time_seconds);

}  // namespace glint::cuda
