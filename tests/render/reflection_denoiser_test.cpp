// The reflection denoiser (render/reflection_denoiser.h, docs/glossy.md) on analytic G-buffers:
// a constant stays constant, nothing bleeds across depth or normal edges, a still camera's history
// converges, and the camera motion vectors find each pixel's surface on the previous frame.
#include "render/reflection_denoiser.h"

#include "gl/gl_test_context.h"
#include "render/render_targets.h"
#include "render/synthetic_gbuffer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace glint::render {
namespace {

using ReflectionDenoiserTest = glint::testing::GlTest;
using testing::CpuGBuffer;
using testing::SyntheticCamera;
using testing::SyntheticScene;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// A reflective floor and a reflective box on it: depth edges (box against floor) and normal edges
// (between the box's faces).
SyntheticScene floor_and_box() {
  SyntheticScene scene;
  scene.add_floor(20.0f, vec3(0.2f), 0.5f);
  scene.add_box(vec3(-0.6f, 0.0f, -0.6f), vec3(0.6f, 1.2f, 0.6f), vec3(0.4f), 0.5f);
  return scene;
}

struct Frame {
  FrameConstants constants;
  CpuGBuffer cpu;
  GlTexture albedo_reflectivity, world_position, world_normal_roughness;
  GlBuffer frame_constants;
};

Frame make_frame(const SyntheticScene& scene, const SyntheticCamera& camera, float roughness) {
  Frame f;
  f.constants = testing::frame_constants_for(camera, kWidth, kHeight);
  f.constants.reflection_sampling = vec4(0.6f, 0.0f, 1.0f, 1.0f);  // glossy on
  f.cpu = testing::rasterize(scene, f.constants, kWidth, kHeight);
  std::vector<vec4> normals = f.cpu.world_normal;
  for (vec4& n : normals) n.w = roughness;
  f.albedo_reflectivity = testing::upload_rgba8(kWidth, kHeight, f.cpu.albedo_reflectivity);
  f.world_position = testing::upload_rgba(kWorldPositionFormat, kWidth, kHeight, f.cpu.world_position);
  f.world_normal_roughness = testing::upload_rgba(kWorldNormalRoughnessFormat, kWidth, kHeight, normals);
  f.frame_constants = create_buffer(sizeof(FrameConstants), &f.constants);
  return f;
}

ResolveSettings no_fade() {
  ResolveSettings s;
  s.fade_end = 0.0f;
  s.denoise = true;
  return s;
}

std::vector<vec4> run(ReflectionDenoiser& denoiser, const Frame& f, const std::vector<vec4>& reflection,
                      const ResolveSettings& settings) {
  const GlTexture image = testing::upload_rgba(kReflectionFormat, kWidth, kHeight, reflection);
  denoiser.run({image.id(), f.world_position.id(), f.world_normal_roughness.id(), f.albedo_reflectivity.id(),
                f.frame_constants.id(), f.constants.view_projection},
               settings);
  return testing::read_rgba_float(denoiser.output(), kWidth, kHeight);
}

bool reflective(const CpuGBuffer& g, std::size_t i) { return g.quad[i] >= 0 && g.albedo_reflectivity[i].w > 0; }

TEST_F(ReflectionDenoiserTest, ConstantImageStaysConstant) {
  const Frame f = make_frame(floor_and_box(), SyntheticCamera{}, 0.5f);
  ReflectionDenoiser denoiser(kWidth, kHeight);
  const vec4 constant(0.25f, 0.5f, 0.75f, 3.0f);
  const std::vector<vec4> input(static_cast<std::size_t>(kWidth * kHeight), constant);
  for (int frame = 0; frame < 3; ++frame) {
    const std::vector<vec4> out = run(denoiser, f, input, no_fade());
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (!reflective(f.cpu, i)) continue;
      ASSERT_NEAR(out[i].x, constant.x, 1e-3f) << "pixel " << i << " frame " << frame;
      ASSERT_NEAR(out[i].y, constant.y, 1e-3f) << "pixel " << i << " frame " << frame;
      ASSERT_NEAR(out[i].z, constant.z, 1e-3f) << "pixel " << i << " frame " << frame;
    }
  }
}

TEST_F(ReflectionDenoiserTest, NothingBleedsAcrossDepthOrNormalEdges) {
  const SyntheticScene scene = floor_and_box();
  const Frame f = make_frame(scene, SyntheticCamera{}, 1.0f);
  // Each visible face its own colour channel pattern: the floor red, every box face green, except
  // the top (parallel to the floor, separated only by depth) blue.
  std::vector<vec4> input(static_cast<std::size_t>(kWidth * kHeight), vec4(0.0f));
  int floor_pixels = 0, box_pixels = 0;
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (f.cpu.quad[i] < 0) continue;
    const testing::SyntheticQuad& quad = scene.quads[static_cast<std::size_t>(f.cpu.quad[i])];
    if (quad.object == 0) {
      input[i] = vec4(1.0f, 0.0f, 0.0f, 1.0f);
      ++floor_pixels;
    } else {
      input[i] = quad.normal.y > 0.5f ? vec4(0.0f, 0.0f, 1.0f, 1.0f) : vec4(0.0f, 1.0f, 0.0f, 1.0f);
      ++box_pixels;
    }
  }
  ASSERT_GT(floor_pixels, 500);
  ASSERT_GT(box_pixels, 100);
  ResolveSettings settings = no_fade();
  settings.denoiser.max_sigma = 8.0f;  // a wide footprint: only the edge weights keep the faces apart
  ReflectionDenoiser denoiser(kWidth, kHeight);
  const std::vector<vec4> out = run(denoiser, f, input, settings);
  int checked = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!reflective(f.cpu, i)) continue;
    const vec3 expected(input[i]);
    // Every channel the face does not have stays (nearly) zero.
    for (int c = 0; c < 3; ++c) {
      if (expected[c] != 0.0f) continue;
      EXPECT_LT(out[i][c], 0.02f) << "pixel " << i << " channel " << c;
    }
    ++checked;
  }
  EXPECT_EQ(checked, floor_pixels + box_pixels);
}

TEST_F(ReflectionDenoiserTest, StillCameraAccumulationConverges) {
  const Frame f = make_frame(floor_and_box(), SyntheticCamera{}, 0.5f);
  ReflectionDenoiser denoiser(kWidth, kHeight);
  std::mt19937 random(3u);
  std::uniform_real_distribution<float> noise(-0.4f, 0.4f);
  const float truth = 0.5f;
  auto mean_error = [&](const std::vector<vec4>& image) {
    double error = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < image.size(); ++i) {
      if (!reflective(f.cpu, i)) continue;
      error += std::abs(image[i].x - truth);
      ++n;
    }
    return error / n;
  };
  ResolveSettings settings = no_fade();
  settings.denoiser.max_history = 64.0f;
  double first = 0.0, last = 0.0;
  for (int frame = 0; frame < 64; ++frame) {
    std::vector<vec4> input(static_cast<std::size_t>(kWidth * kHeight));
    for (vec4& v : input) v = vec4(truth + noise(random), 0.0f, 0.0f, 1.0f);
    run(denoiser, f, input, settings);
    const double error = mean_error(testing::read_rgba_float(denoiser.accumulated(), kWidth, kHeight));
    if (frame == 0) first = error;
    last = error;
  }
  EXPECT_GT(first, 0.15) << "one frame is the noisy input";
  EXPECT_LT(last, 0.03) << "64 frames of history average the noise away";
}

TEST_F(ReflectionDenoiserTest, CameraMotionVectorsFindEachPixelsPreviousPosition) {
  const SyntheticScene scene = floor_and_box();
  SyntheticCamera before;
  SyntheticCamera after = before;
  after.position += vec3(0.35f, 0.1f, -0.2f);
  after.target += vec3(0.1f, 0.0f, 0.0f);
  const Frame previous = make_frame(scene, before, 0.5f);
  const Frame current = make_frame(scene, after, 0.5f);
  ReflectionDenoiser denoiser(kWidth, kHeight);
  denoiser.record_motion(true);
  const std::vector<vec4> input(static_cast<std::size_t>(kWidth * kHeight), vec4(0.5f, 0.5f, 0.5f, 1.0f));
  run(denoiser, previous, input, no_fade());
  run(denoiser, current, input, no_fade());
  const std::vector<vec2> motion = denoiser.read_motion();
  int mapped = 0, reflective_pixels = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = current.cpu.index(x, y);
      if (!reflective(current.cpu, i)) continue;
      ++reflective_pixels;
      if (motion[i].x < 0.0f) continue;
      ++mapped;
      const vec3 world(current.cpu.world_position[i]);
      // The analytic answer: the surface point seen through the previous camera.
      const vec2 expected = testing::project_to_pixels(previous.constants, world);
      ASSERT_NEAR(motion[i].x, expected.x, 2e-3f) << x << "," << y;
      ASSERT_NEAR(motion[i].y, expected.y, 2e-3f) << x << "," << y;
      // And the previous frame saw this surface there: one of the bilinear taps around the
      // position is the same rectangle.
      bool same = false;
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx) {
          const int px = std::clamp(static_cast<int>(std::floor(motion[i].x - 0.5f)) + dx, 0, kWidth - 1);
          const int py = std::clamp(static_cast<int>(std::floor(motion[i].y - 0.5f)) + dy, 0, kHeight - 1);
          same = same || previous.cpu.quad[previous.cpu.index(px, py)] == current.cpu.quad[i];
        }
      EXPECT_TRUE(same) << x << "," << y;
    }
  EXPECT_GT(mapped, reflective_pixels * 8 / 10) << "most of the floor and box stay in view";
  EXPECT_LT(mapped, reflective_pixels) << "the pixels the move uncovered restart their history";
}

}  // namespace
}  // namespace glint::render
