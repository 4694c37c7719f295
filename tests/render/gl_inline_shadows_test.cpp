// The gl backend's inline-traced shadow rays (RayTracingSettings::gl_inline_shadow_rays,
// rt::GlTracing::bind_inline_tracing): the dense shadow mask made, traced and written in one dispatch
// equals the three steps' (ray list, trace_any_gl, mask pass) pixel for pixel, rt and hybrid, on
// atrium-simple and on an atrium frame; the reflection trace that traces its hits' shadow rays in
// the same invocation writes the same hits and answers as the closest-hit trace, the hit shadow
// ray pass and the occlusion query, and the frames are equal; the gl masks equal the cpu backend's; the
// hits' answers are kept without a ray list.
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

// What the reflection trace leaves for hit shading, by pixel (the ray list's order comes from
// atomics, so it may differ between runs): the hits and the hits' shadow answers, read back from the
// GL buffers.
struct TracedHits {
  std::map<std::uint32_t, accel::Hit> hits;
  std::map<std::uint32_t, std::uint32_t> occluded;
  ImageRgba8 frame{1, 1};
};

template <typename T>
std::vector<T> read_buffer(GLuint buffer, std::size_t count) {
  std::vector<T> values(count);
  glGetNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(count * sizeof(T)), values.data());
  return values;
}

TracedHits render_traced_hits(const PosedFrame& posed, const FramePipelineSettings& settings) {
  FramePipeline pipeline(posed.scene, 160, 90, settings);
  pipeline.render(posed.frame);
  const std::uint32_t count = pipeline.ray_trace_stats()->rays_traced;
  EXPECT_GT(count, 1000u);
  const RayTracedReflections& reflections = *pipeline.ray_traced_reflections();
  EXPECT_EQ(reflections.hit_shadow_rays()->traced_with_hits(), settings.ray_tracing.gl_inline_shadow_rays);
  const auto pixels = read_buffer<std::uint32_t>(reflections.ray_buffers().pixel_buffer(), count);
  const auto hits = read_buffer<accel::Hit>(reflections.ray_buffers().hit_buffer(), count);
  const auto occluded = read_buffer<std::uint32_t>(reflections.hit_shadow_rays()->answers().answer_buffer(), count);
  TracedHits traced;
  for (std::uint32_t i = 0; i < count; ++i) {
    traced.hits[pixels[i]] = hits[i];
    traced.occluded[pixels[i]] = occluded[i];
  }
  EXPECT_EQ(traced.hits.size(), count) << "one ray per pixel";
  traced.frame = pipeline.read_final();
  return traced;
}

bool same_hit(const accel::Hit& a, const accel::Hit& b) {
  return a.t == b.t && a.instance == b.instance && a.prim == b.prim && a.u == b.u && a.v == b.v;
}

TEST_F(GlInlineShadowsTest, HitsAndTheirShadowsEqualTheThreeSteps) {
  const PosedFrame posed("atrium-simple", 2100);
  for (const ShadowMethod method : {ShadowMethod::rt, ShadowMethod::hybrid}) {
    SCOPED_TRACE(shadow_method_name(method));
    const TracedHits fused = render_traced_hits(posed, gl_settings(method, ReflectionMode::rt, true));
    const TracedHits steps = render_traced_hits(posed, gl_settings(method, ReflectionMode::rt, false));
    ASSERT_EQ(fused.hits.size(), steps.hits.size());
    std::size_t hit_mismatches = 0, answer_mismatches = 0, occluded = 0;
    for (const auto& [pixel, hit] : fused.hits) {
      ASSERT_TRUE(steps.hits.contains(pixel)) << "pixel " << pixel << " traced by one path only";
      hit_mismatches += !same_hit(hit, steps.hits.at(pixel));
      answer_mismatches += fused.occluded.at(pixel) != steps.occluded.at(pixel);
      occluded += fused.occluded.at(pixel) != 0;
    }
    EXPECT_EQ(hit_mismatches, 0u);
    EXPECT_EQ(answer_mismatches, 0u);
    EXPECT_GT(occluded, fused.hits.size() / 20) << "shadows are seen in the floor's reflection";
    EXPECT_TRUE(fused.frame.pixels == steps.frame.pixels) << "the final frames differ";
  }
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

// The hits' shadow answers of the inline trace are kept without a ray list; only the gl backend traces
// that way, and such buffers cannot be traced by anyone else.
TEST_F(GlInlineShadowsTest, AnswersWithoutRaysAreTheGlBackendsOnly) {
  const Scene scene = make_preset("atrium-simple");
  const std::unique_ptr<rt::RayTracer> cpu = build_ray_tracer(scene, {});
  try {
    OcclusionBuffers buffers(16, *cpu, "test rays", RayQuery::any, RayStorage::answers_only);
    ADD_FAILURE() << "the cpu backend got answers without rays";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not the cpu backend"), std::string::npos) << error.what();
  }
  gl_rt::GlRayTracer gl;
  gl.build(scene, {});
  OcclusionBuffers answers(16, gl, "test rays", RayQuery::any, RayStorage::answers_only);
  try {
    answers.trace(16);
    ADD_FAILURE() << "traced answers without rays";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("no rays to trace"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace glint::render
