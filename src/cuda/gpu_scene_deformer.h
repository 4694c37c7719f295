#pragma once
// The paper's sine deformer on the GPU (--deform-on gpu): every deformable mesh is posed by CUDA
// kernels from its rest pose, with smooth normals recomputed on the GPU, written straight into the
// GL vertex buffer (shared with CUDA) and into a GPU ray tracer's own copy of the positions, so a
// deforming frame moves no vertex through the host. The formulas and the normal gathering are the
// CPU deformer's (scene/sine_deform_math.h, SineDeformer's vertex -> triangle adjacency).
// Plain C++ (no CUDA or GL headers); a build without CUDA throws at construction.
#include "rt/ray_tracer.h"
#include "scene/scene.h"
#include "scene/sine_deformer.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace glint::cuda {

// The GL vertex the deformer rewrites: xyz from the deformer, w (the uv) kept. Equal to
// render::GpuVertex (checked there).
struct DeformedGlVertex {
  vec4 position_u;
  vec4 normal_v;
};
static_assert(sizeof(DeformedGlVertex) == 32);

class GpuSceneDeformer {
public:
  // `deformers`: the CPU deformers of the scene (their rest poses, parameters and adjacency are
  // uploaded once). `gl_vertex_buffer`: the GL buffer of DeformedGlVertex holding mesh m's vertices
  // from `base_vertex[m]` on (indexed by scene mesh); 0 = do not write GL. `tracer`: a GPU ray
  // tracer whose device_positions() are rewritten too, or null. Work runs on the tracer's stream
  // (so its update sees the new positions), else on a stream of its own. Needs a CUDA GPU and, with
  // a GL buffer, the GL context current; glint::Error otherwise.
  GpuSceneDeformer(const SceneDeformers& deformers, std::uint32_t gl_vertex_buffer,
                   std::vector<std::uint32_t> base_vertex, rt::DeviceTracing* tracer);
  ~GpuSceneDeformer();
  GpuSceneDeformer(const GpuSceneDeformer&) = delete;
  GpuSceneDeformer& operator=(const GpuSceneDeformer&) = delete;

  // Enqueues the pose of every deformable mesh at `frame` (the CPU deformer's time) and returns the
  // meshes it changed, ascending. Returns before the GPU is done.
  std::vector<std::uint32_t> apply(int frame);
  // The ticket of the last apply()'s kernels (not the wait for GL the mapping adds before them),
  // for apply_ms; glint::Error before the first apply().
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
