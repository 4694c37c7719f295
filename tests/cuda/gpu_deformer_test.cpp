// The GPU sine deformer poses meshes like the CPU one (same formulas, same normal gathering), up to
// the GPU's sinf and fused multiply-adds. Needs a CUDA GPU; skipped elsewhere.
#include "cuda/device_query.h"
#include "cuda/gpu_scene_deformer.h"
#include "core/error.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"

#include <gtest/gtest.h>

#include <algorithm>

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

}  // namespace
}  // namespace glint
