// The GPU sine deformer poses meshes like the CPU one (same formulas, same normal gathering), up to
// the GPU's sinf and fused multiply-adds, both through pose_mesh_on_gpu (positions and normals) and
// through GpuSceneDeformer, the frame path (positions only, into the tracer's device positions).
// Needs a CUDA GPU; skipped elsewhere.
#include "cuda/device_copies.h"
#include "cuda/device_query.h"
#include "cuda/gpu_scene_deformer.h"
#include "core/error.h"
#include "rt/ray_tracer.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace glint {
namespace {

float max_difference(const std::vector<vec3>& a, const std::vector<vec3>& b) {
  float worst = 0.0f;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const vec3 d = glm::abs(a[i] - b[i]);
    worst = std::max({worst, d.x, d.y, d.z});
  }
  return worst;
}

TEST(GpuDeformer, PosesTheAtriumDinosaursLikeTheCpuDeformerWithin1e5) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = make_preset("atrium-simple");
  const SceneDeformers deformers(scene);
  ASSERT_FALSE(deformers.empty());
  for (const int frame : {0, 1800, 2100, 4400}) {
    const float time = deformers.time_at(frame);
    for (std::size_t k = 0; k < deformers.meshes().size(); ++k) {
      Mesh cpu = scene.meshes[deformers.meshes()[k]];
      SineDeformer(cpu, deformers.deformers()[k].parameters()).apply(cpu, time);
      const cuda::GpuPosedMesh gpu = cuda::pose_mesh_on_gpu(deformers.deformers()[k], time);
      ASSERT_EQ(gpu.positions.size(), cpu.positions.size());
      ASSERT_EQ(gpu.normals.size(), cpu.normals.size());
      EXPECT_LE(max_difference(gpu.positions, cpu.positions), 1e-5f) << "frame " << frame << " mesh " << k;
      EXPECT_LE(max_difference(gpu.normals, cpu.normals), 1e-5f) << "frame " << frame << " mesh " << k;
      EXPECT_GT(max_difference(gpu.positions, scene.meshes[deformers.meshes()[k]].positions), 0.0f)
          << "the pose must differ from the rest pose (frame " << frame << ")";
    }
  }
}

TEST(GpuDeformer, WithoutAGpuIsOneClearError) {
  if (cuda_gpu_present()) GTEST_SKIP() << "this machine has a CUDA GPU";
  const Scene scene = make_preset("atrium-simple");
  const SceneDeformers deformers(scene);
  ASSERT_FALSE(deformers.empty());
  try {
    (void)cuda::pose_mesh_on_gpu(deformers.deformers()[0], 1.0f);
    FAIL() << "expected glint::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("CUDA"), std::string::npos) << error.what();
  }
}

#if GLINT_HAVE_CUDA
// The device side of a GPU tracer reduced to what GpuSceneDeformer uses: a stream and each mesh's
// device positions (null for a mesh it has none of). Anything else is a test failure.
class PositionsOnlyTracing final : public rt::DeviceTracing {
public:
  PositionsOnlyTracing(std::vector<vec3*> positions, cudaStream_t stream)
      : positions_(std::move(positions)), stream_(stream) {}

  void* stream() override { return stream_; }
  vec3* device_positions(uint32_t mesh) override { return positions_.at(mesh); }
  rt::GpuTicket trace_closest_device(const accel::Ray*, accel::Hit*, const uint32_t*, uint32_t) override {
    ADD_FAILURE() << "the deformer traces nothing";
    return 0;
  }
  rt::GpuTicket trace_any_device(const accel::Ray*, uint32_t*, const uint32_t*, uint32_t) override {
    ADD_FAILURE() << "the deformer traces nothing";
    return 0;
  }
  std::optional<double> gpu_ms(rt::GpuTicket, bool) override {
    ADD_FAILURE() << "the deformer reads no tracer time";
    return std::nullopt;
  }
  void drop_ticket(rt::GpuTicket) override { ADD_FAILURE() << "the deformer drops no tracer ticket"; }
  void update_device(std::span<const uint32_t>, rt::UpdatePolicy) override {
    ADD_FAILURE() << "the deformer leaves the update to the frame pipeline";
  }

private:
  std::vector<vec3*> positions_;
  cudaStream_t stream_;
};

// The frame path: GpuSceneDeformer::apply writes the CPU deformer's positions into the tracer's
// device positions of every deformable mesh, on the tracer's stream.
TEST(GpuDeformer, SceneDeformerPosesTheTracersDevicePositionsLikeTheCpuDeformer) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = make_preset("atrium-simple");
  const SceneDeformers deformers(scene);
  ASSERT_FALSE(deformers.empty());
  std::vector<vec3*> positions(scene.meshes.size(), nullptr);
  for (const std::uint32_t m : deformers.meshes()) positions[m] = testing::device_copy(scene.meshes[m].positions);
  cudaStream_t stream = nullptr;
  ASSERT_EQ(cudaStreamCreateWithFlags(&stream, cudaStreamNonBlocking), cudaSuccess);
  {
    PositionsOnlyTracing tracer(positions, stream);
    cuda::GpuSceneDeformer deformer(deformers, tracer);
    for (const int frame : {0, 2100}) {
      EXPECT_EQ(deformer.apply(frame), deformers.meshes());
      ASSERT_EQ(cudaStreamSynchronize(stream), cudaSuccess);
      Scene cpu = scene;
      SceneDeformers(cpu).apply(cpu, frame);
      for (const std::uint32_t m : deformers.meshes()) {
        const std::vector<vec3> gpu = testing::host_copy(positions[m], scene.meshes[m].positions.size());
        EXPECT_LE(max_difference(gpu, cpu.meshes[m].positions), 1e-5f) << "frame " << frame << " mesh " << m;
        EXPECT_GT(max_difference(gpu, scene.meshes[m].positions), 0.0f) << "frame " << frame << " mesh " << m;
      }
    }
    EXPECT_TRUE(deformer.apply_ms(deformer.last_apply(), true).has_value());
  }
  for (vec3* p : positions) cudaFree(p);
  cudaStreamDestroy(stream);
}

// Positions are required: a tracer without device positions for a deformable mesh is one clear
// error naming the mesh, not a pose written into scratch memory nobody reads.
TEST(GpuDeformer, SceneDeformerWithoutDevicePositionsIsAClearError) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = make_preset("atrium-simple");
  const SceneDeformers deformers(scene);
  ASSERT_FALSE(deformers.empty());
  PositionsOnlyTracing tracer(std::vector<vec3*>(scene.meshes.size(), nullptr), nullptr);
  cuda::GpuSceneDeformer deformer(deformers, tracer);
  const std::string error = testing::error_of([&] { (void)deformer.apply(1); });
  EXPECT_NE(error.find(deformers.deformers()[0].mesh_name()), std::string::npos) << error;
  EXPECT_NE(error.find("positions"), std::string::npos) << error;
}
#endif

}  // namespace
}  // namespace glint
