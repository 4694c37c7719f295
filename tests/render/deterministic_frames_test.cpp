// The same frame rendered again gives the same image, bit for bit, in every ray-traced mode and on
// every backend this machine has. Rays are listed in a run-dependent order (work groups take their
// slots by atomics), so anything in ray tracing or hit shading that depends on a ray's neighbours in
// the list shows up here. It did: llvmpipe answered textureSize() for one lane's mip level in every
// lane of a SIMD group, and rt frames on the cpu and embree backends differed from run to run by
// 35-38 dB (docs/reliability.md, "Deterministic frames").
#include "cuda/device_query.h"
#include "render/frame_pipeline.h"
#include "rt/ray_tracer.h"
#include "scene/camera_path.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glint::render {
namespace {

using DeterministicFramesTest = testing::GlTest;

std::vector<std::string> backends_here() {
  std::vector<std::string> backends{"cpu", "embree"};
  if (cuda_gpu_present()) {
    backends.emplace_back("cuda");
    if (GLINT_HAVE_OPTIX) backends.emplace_back("optix");
  }
  return backends;
}

TEST_F(DeterministicFramesTest, RtAndHybridFramesAreTheSameEveryTime) {
  Scene scene = make_preset("atrium-simple");
  SceneDeformers(scene).apply(scene, 2100);
  const FrameState frame = WalkthroughAnimation(scene).at(2100);
  for (const std::string& backend : backends_here()) {
    for (const ReflectionMode mode : {ReflectionMode::rt, ReflectionMode::hybrid}) {
      FramePipelineSettings settings;
      settings.reflections = mode;
      settings.resolve.blur_radius = 0;  // a differing pixel stays one pixel
      settings.ray_tracing.backend = backend;
      FramePipeline pipeline(scene, 320, 180, settings);
      pipeline.render(frame);
      const ImageRgba8 first = pipeline.read_final();
      for (int run = 1; run < 5; ++run) {
        pipeline.render(frame);
        const ImageRgba8 again = pipeline.read_final();
        std::size_t differing = 0;
        for (std::size_t i = 0; i < first.pixels.size(); ++i) differing += first.pixels[i] != again.pixels[i];
        EXPECT_EQ(differing, 0u) << backend << " " << reflection_mode_name(mode) << ", render " << run + 1;
      }
    }
  }
}

}  // namespace
}  // namespace glint::render
