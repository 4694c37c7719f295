// The gl backend's inline-traced shadow rays (RayTracingSettings::gl_inline_shadow_rays,
// rt::GlTracing::bind_inline_tracing): the dense shadow mask made, traced and written in one dispatch
// equals the three steps' (ray list, trace_any_gl, mask pass) pixel for pixel, rt and hybrid, on
// atrium-simple and on an atrium frame, and equals the cpu backend's; so does a whole hybrid frame.
// (The reflection hits' shadow rays take the three steps with every backend but cuda: made and
// traced in one pass, they took twice as long on an H100, docs/perf.md "Eleventh round".)
#include "gl_rt/gl_ray_tracer.h"
#include "render/frame_pipeline.h"
#include "render/shadow_ray_index.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"
#include "../gl/gl_test_context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace glint::render {
namespace {

using GlInlineShadowsTest = testing::GlTest;

// A preset with its dinosaurs posed at `frame_number`, and that frame's camera and light.
struct PosedFrame {
  Scene scene;
  FrameState frame;
  PosedFrame(const char* preset, int frame_number) : scene(make_preset(preset)) {
    SceneDeformers(scene).apply(scene, frame_number);
    frame = WalkthroughAnimation(scene).at(frame_number);
  }
};

FramePipelineSettings gl_settings(ShadowMethod shadows, ReflectionMode reflections, bool inline_trace,
                                  const char* backend = "gl") {
  FramePipelineSettings settings;
  settings.reflections = reflections;
  settings.shadows.method = shadows;
  settings.ray_tracing.backend = backend;
  settings.ray_tracing.gl_inline_shadow_rays = inline_trace;
  return settings;
}

std::vector<std::uint8_t> shadow_mask_bytes(const FramePipeline& pipeline) {
  std::vector<std::uint8_t> bytes;
  for (const vec4& p : pipeline.raster().read_rgbaf(RasterOutput::ShadowMask).pixels)
    bytes.push_back(static_cast<std::uint8_t>(std::lround(p.x * 255.0f)));
  return bytes;
}

std::vector<std::uint8_t> render_mask(const PosedFrame& posed, const FramePipelineSettings& settings, int width,
                                      int height) {
  FramePipeline pipeline(posed.scene, width, height, settings);
  pipeline.render(posed.frame);
  EXPECT_EQ(pipeline.shadow_rays()->traces_inline(),
            settings.ray_tracing.backend == "gl" && settings.ray_tracing.gl_inline_shadow_rays);
  return shadow_mask_bytes(pipeline);
}

std::size_t count_differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) differ += a[i] != b[i];
  return differ;
}

// The inline mask equals the three steps' (the same ray, the same walk), for rt and hybrid, and has
// shadows and lit pixels; with `against_cpu`, it equals the cpu backend's mask too.
void expect_inline_mask_equals_three_steps(const PosedFrame& posed, int width, int height, bool against_cpu) {
  for (const ShadowMethod method : {ShadowMethod::rt, ShadowMethod::hybrid}) {
    SCOPED_TRACE(shadow_method_name(method));
    const auto inline_mask = render_mask(posed, gl_settings(method, ReflectionMode::off, true), width, height);
    const auto three_steps = render_mask(posed, gl_settings(method, ReflectionMode::off, false), width, height);
    EXPECT_EQ(count_differing(inline_mask, three_steps), 0u);
    if (against_cpu) {
      const auto cpu = render_mask(posed, gl_settings(method, ReflectionMode::off, false, "cpu"), width, height);
      EXPECT_EQ(count_differing(inline_mask, cpu), 0u) << "llvmpipe traces as the cpu backend does";
    }
    std::size_t shadowed = 0, lit = 0;
    for (const std::uint8_t value : inline_mask) (value == 0 ? shadowed : lit) += value == 0 || value == 255;
    EXPECT_GT(shadowed, inline_mask.size() / 50);
    EXPECT_GT(lit, inline_mask.size() / 4);
  }
}

TEST_F(GlInlineShadowsTest, DenseMaskEqualsTheThreeStepsOnAtriumSimple) {
  // 163 x 91: the last column of blocks is 3 pixels wide and the last band 3 rows high.
  expect_inline_mask_equals_three_steps(PosedFrame("atrium-simple", 2300), 163, 91, /*against_cpu=*/true);
}

TEST_F(GlInlineShadowsTest, DenseMaskEqualsTheThreeStepsOnAnAtriumFrame) {
  // The atrium's 618k triangles: the gl backend's structures are built twice per method, so no cpu run.
  expect_inline_mask_equals_three_steps(PosedFrame("atrium", 2100), 96, 54, /*against_cpu=*/false);
}

// The whole frame of the CLI's gl run (hybrid reflections, rt shadows) equals the cpu backend's on
// llvmpipe, as it did with the three steps.
TEST_F(GlInlineShadowsTest, HybridFrameEqualsTheCpuBackends) {
  const PosedFrame posed("atrium-simple", 2100);
  const auto frame = [&](const char* backend) {
    FramePipeline pipeline(posed.scene, 160, 90, gl_settings(ShadowMethod::rt, ReflectionMode::hybrid, true, backend));
    pipeline.render(posed.frame);
    return pipeline.read_final();
  };
  EXPECT_TRUE(frame("gl").pixels == frame("cpu").pixels);
}

TEST_F(GlInlineShadowsTest, BindingAProgramWithoutTheWalkIsOneLine) {
  gl_rt::GlRayTracer tracer;
  const ShaderProgram program = ShaderProgram::from_embedded({"shadow_ray_mask.comp.glsl"});
  try {
    tracer.bind_inline_tracing(program.id());
    ADD_FAILURE() << "bound before build()";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("before build()"), std::string::npos) << error.what();
  }
  tracer.build(make_preset("atrium-simple"), {});
  try {
    tracer.bind_inline_tracing(program.id());
    ADD_FAILURE() << "a program without the walk was bound";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("no tlas_node_count uniform"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace glint::render
