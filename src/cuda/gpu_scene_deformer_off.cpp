// A build without CUDA: the GPU deformer is unavailable, said at construction.
#include "cuda/gpu_scene_deformer.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {

struct GpuSceneDeformer::State {};

GpuSceneDeformer::GpuSceneDeformer(const SceneDeformers&, rt::DeviceTracing&) {
  fail("--deform-on gpu: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}
GpuSceneDeformer::~GpuSceneDeformer() = default;
std::vector<std::uint32_t> GpuSceneDeformer::apply(int) { return {}; }
std::uint64_t GpuSceneDeformer::last_apply() const { return 0; }
std::optional<double> GpuSceneDeformer::apply_ms(std::uint64_t, bool) { return std::nullopt; }

GpuPosedMesh pose_mesh_on_gpu(const SineDeformer&, float) {
  fail("the GPU deformer: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}

}  // namespace glint::cuda
#endif
