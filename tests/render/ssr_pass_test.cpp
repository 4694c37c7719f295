// SsrPass on analytic G-buffers: every trusted hit must be what the CPU ray caster says the mirror
// ray really hits (colour and distance), and every reflection that cannot be seen on screen (sky,
// behind the camera, off screen, back faces) must land in the failure mask.
#include "render/ssr_pass.h"

#include "gl/gl_test_context.h"
#include "render/ssr_test_run.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace glint::render {
namespace {

using testing::CpuGBuffer;
using testing::reflective;
using testing::SurfaceHit;
using testing::SyntheticCamera;
using testing::SyntheticScene;

constexpr int kWidth = 64;
constexpr int kHeight = 48;
const vec3 kBoxLit{0.9f, 0.2f, 0.1f};
const vec3 kFloorLit{0.1f, 0.1f, 0.1f};

using SsrResult = testing::SsrRun;

SsrResult run_ssr(const SyntheticScene& scene, const SyntheticCamera& camera, const SsrSettings& settings = {}) {
  return testing::run_ssr(scene, camera, kWidth, kHeight, 7, settings);
}

// Where the mirror ray of pixel i really goes (CPU ray cast from the G-buffer's surface point).
std::optional<SurfaceHit> mirror_hit(const SyntheticScene& scene, const SsrResult& r, std::size_t i) {
  const vec3 p(r.cpu.world_position[i]);
  const vec3 n(r.cpu.world_normal[i]);
  const vec3 ray = glm::reflect(glm::normalize(p - vec3(r.constants.camera_position)), n);
  return testing::trace(scene, p, ray, 1e-3f);
}

// A mirror hit that screen space can certainly resolve: well inside the screen (beyond the edge
// fade band), on a pixel whose 3x3 neighbourhood shows the same rectangle (no silhouette), the
// surface point visible from the camera, and not at the contact line with the mirror.
bool clearly_on_screen(const SyntheticScene& scene, const SsrResult& r, const SurfaceHit& hit,
                       const SsrSettings& settings) {
  const vec2 q = testing::project_to_pixels(r.constants, hit.position);
  const float margin = settings.edge_fade * kHeight + 3.0f;
  if (q.x < margin || q.y < margin || q.x > kWidth - margin || q.y > kHeight - margin) return false;
  // A hit next to a silhouette may be refused (the confidence's silhouette term).
  const int reach = 2;
  const int qx = static_cast<int>(q.x), qy = static_cast<int>(q.y);
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx)
      if (r.cpu.quad[r.cpu.index(qx + dx, qy + dy)] != hit.quad) return false;
  const float eye_distance = glm::length(hit.position - vec3(r.constants.camera_position));
  if (std::abs(r.cpu.t[r.cpu.index(qx, qy)] - eye_distance) > 0.05f * eye_distance) return false;
  (void)scene;
  return hit.t > 0.3f;
}

bool is_object(const SyntheticScene& scene, const std::optional<SurfaceHit>& hit, int object) {
  return hit && scene.quads[static_cast<std::size_t>(hit->quad)].object == object;
}

// Whether the mirror ray of a neighbour of (x, y) hits `object`.
bool near_reflection_of(const SyntheticScene& scene, const SsrResult& r, int x, int y, int object) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= kWidth || ny >= kHeight) continue;
      const std::size_t j = r.cpu.index(nx, ny);
      if (reflective(r.cpu, j) && is_object(scene, mirror_hit(scene, r, j), object)) return true;
    }
  }
  return false;
}

// A readable map for failure messages: '.' not reflective, 'H' hit, 'F' failed, ' ' background.
std::string ascii_map(const SsrResult& r) {
  std::string map;
  for (int y = kHeight - 1; y >= 0; --y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = r.cpu.index(x, y);
      map += r.cpu.quad[i] < 0 ? ' ' : !reflective(r.cpu, i) ? '.' : r.mask[i] ? 'F' : 'H';
    }
    map += '\n';
  }
  return map;
}

// Mirror floor, camera above it, a box standing on the floor in front of the camera.
struct FloorAndBox {
  SyntheticScene scene;
  int floor = 0;
  int box = 0;
  SyntheticCamera camera;
  explicit FloorAndBox(float box_reflectivity = 0.0f) {
    floor = scene.add_floor(50.0f, kFloorLit, 1.0f);
    box = scene.add_box(vec3(-1.2f, 0.0f, -2.5f), vec3(1.2f, 1.6f, -1.5f), kBoxLit, box_reflectivity);
    camera.position = vec3(0.0f, 1.4f, 3.0f);
    camera.target = vec3(0.0f, 0.5f, -1.0f);
  }
};

using SsrPassLimits = glint::testing::GlTest;
using SsrPassErrors = glint::testing::GlTest;

class SsrPassTest : public glint::testing::GlTest, public ::testing::WithParamInterface<SsrSettings> {};

TEST_P(SsrPassTest, MirrorFloorReflectsTheBoxWithItsColourAndDistance) {
  const SsrSettings settings = GetParam();
  const FloorAndBox setup;
  const SsrResult r = run_ssr(setup.scene, setup.camera, settings);

  int checked = 0, wrong_colour = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = r.cpu.index(x, y);
      if (!reflective(r.cpu, i)) continue;
      const auto hit = mirror_hit(setup.scene, r, i);
      const vec4 found = r.reflection[i];
      // Nothing but the box can be reflected here: any trusted hit must have its colour.
      if (r.mask[i] == 0 && glm::length(vec3(found) - kBoxLit) > 0.02f) ++wrong_colour;
      if (!hit) {
        // At the reflection's silhouette a pixel's footprint covers both sky and box; elsewhere a
        // mirror ray to the sky must fail.
        if (!near_reflection_of(setup.scene, r, x, y, setup.box)) {
          EXPECT_EQ(r.mask[i], 1) << "mirror ray to the sky must fail at " << x << "," << y;
        }
        continue;
      }
      if (!is_object(setup.scene, hit, setup.box) || !clearly_on_screen(setup.scene, r, *hit, settings)) continue;
      ++checked;
      EXPECT_EQ(r.mask[i], 0) << "pixel " << x << "," << y << " should be an SSR hit\n" << ascii_map(r);
      EXPECT_NEAR(found.x, kBoxLit.x, 0.01f) << x << "," << y;
      EXPECT_NEAR(found.y, kBoxLit.y, 0.01f) << x << "," << y;
      EXPECT_NEAR(found.z, kBoxLit.z, 0.01f) << x << "," << y;
      EXPECT_NEAR(found.w, hit->t, 0.04f * hit->t) << "reflection distance at " << x << "," << y;
    }
  }
  EXPECT_EQ(wrong_colour, 0) << ascii_map(r);
  EXPECT_GE(checked, 40) << "the scene must put the box's reflection on many floor pixels";
}

// A box face whose lit colour changes across it: SSR's colour at a trusted hit must be the colour
// where the mirror ray meets the face, not the colour at the centre of the pixel it met (half a
// pixel of the gradient away at worst): the reflection of a textured or shaded wall must not be
// shifted by up to half a pixel.
TEST_P(SsrPassTest, TheColourOfAHitIsTakenWhereTheRayMeetsTheSurface) {
  const SsrSettings settings = GetParam();
  FloorAndBox setup;
  // Red from 0.2 at the box's left edge to 0.8 at its right (the face towards the camera is +z).
  for (testing::SyntheticQuad& quad : setup.scene.quads)
    if (quad.object == setup.box) {
      quad.lit = vec3(0.5f, 0.2f, 0.1f);
      quad.lit_per_x = vec3(0.25f, 0.0f, 0.0f);
    }
  const SsrResult r = run_ssr(setup.scene, setup.camera, settings);
  double error_sum = 0.0;
  float largest = 0.0f;
  int checked = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = r.cpu.index(x, y);
      if (!reflective(r.cpu, i) || r.mask[i] != 0) continue;
      const auto hit = mirror_hit(setup.scene, r, i);
      if (!is_object(setup.scene, hit, setup.box) || !clearly_on_screen(setup.scene, r, *hit, settings)) continue;
      const vec3 expected = testing::lit_at(setup.scene.quads[static_cast<std::size_t>(hit->quad)], hit->position);
      const float error = std::abs(r.reflection[i].x - expected.x);
      error_sum += error;
      largest = std::max(largest, error);
      ++checked;
    }
  }
  ASSERT_GE(checked, 40) << "the scene must put the box's reflection on many floor pixels";
  // One pixel of the box spans about 0.027 of red here. Measured on llvmpipe: the pixel centre's
  // colour (before) was off by 0.0068 on the mean and up to 0.0136, half a pixel; where the ray meets
  // the face, by 0.00034 and up to 0.00074 (the half float's rounding and the interpolation's).
  EXPECT_LE(error_sum / checked, 0.001) << "mean error of the reflected colour over " << checked << " hits";
  EXPECT_LE(largest, 0.003f);
}

// FramePipeline's order around one GL-CUDA hand-over (docs/ssr.md "March, then colour"): the march
// before lighting, without the lit image, and the colour fetch after it give run()'s outputs exactly.
TEST_P(SsrPassTest, MarchThenShadeEqualsOneDispatch) {
  FloorAndBox setup(0.4f);  // the box reflects too
  for (testing::SyntheticQuad& quad : setup.scene.quads)
    if (quad.object == setup.box) quad.lit_per_x = vec3(0.25f, 0.0f, 0.0f);  // a colour that varies in a pixel
  const SsrResult one = testing::run_ssr(setup.scene, setup.camera, kWidth, kHeight, 7, GetParam());
  const SsrResult split = testing::run_ssr(setup.scene, setup.camera, kWidth, kHeight, 7, GetParam(),
                                           testing::SsrDispatch::march_then_shade);
  int hits = 0;
  for (std::size_t i = 0; i < one.mask.size(); ++i) hits += reflective(one.cpu, i) && one.mask[i] == 0;
  ASSERT_GE(hits, 40) << "the scene must give SSR many trusted hits";
  EXPECT_EQ(split.mask, one.mask);
  EXPECT_EQ(split.reflection, one.reflection);
  EXPECT_EQ(split.counts.reflective, one.counts.reflective);
  EXPECT_EQ(split.counts.failed, one.counts.failed);
}

TEST_P(SsrPassTest, CountersMatchTheMaskAndNonReflectivePixelsNeverFail) {
  const FloorAndBox setup(0.4f);  // the box reflects too: its rays head back past the camera
  const SsrResult r = run_ssr(setup.scene, setup.camera, GetParam());
  std::uint32_t reflective_pixels = 0, mask_sum = 0;
  for (std::size_t i = 0; i < r.mask.size(); ++i) {
    mask_sum += r.mask[i];
    if (reflective(r.cpu, i)) {
      ++reflective_pixels;
    } else {
      EXPECT_EQ(r.mask[i], 0) << "non-reflective pixel " << i << " is marked failed";
      EXPECT_EQ(r.reflection[i], vec4(0.0f)) << "non-reflective pixel " << i << " got a reflection";
    }
    if (r.mask[i] != 0) {
      EXPECT_EQ(r.reflection[i], vec4(0.0f)) << "failed pixel " << i << " kept a reflection";
    }
    EXPECT_LE(r.mask[i], 1);
  }
  EXPECT_GT(reflective_pixels, 1000u);
  EXPECT_GT(mask_sum, 0u);
  EXPECT_LT(mask_sum, reflective_pixels);
  EXPECT_EQ(r.counts.reflective, reflective_pixels);
  EXPECT_EQ(r.counts.failed, mask_sum);
}

TEST_P(SsrPassTest, FloorWithNothingAboveItFailsEverywhere) {
  SyntheticScene scene;
  scene.add_floor(50.0f, kFloorLit, 1.0f);
  SyntheticCamera camera;
  camera.position = vec3(0.0f, 1.5f, 0.0f);
  camera.target = vec3(0.0f, 0.0f, -4.0f);
  const SsrResult r = run_ssr(scene, camera, GetParam());
  std::uint32_t reflective_pixels = 0;
  for (std::size_t i = 0; i < r.mask.size(); ++i) {
    if (!reflective(r.cpu, i)) continue;
    ++reflective_pixels;
    EXPECT_EQ(r.mask[i], 1) << "pixel " << i;
    EXPECT_EQ(r.reflection[i], vec4(0.0f));
  }
  EXPECT_GT(reflective_pixels, 1000u);
  EXPECT_EQ(r.counts.reflective, reflective_pixels);
  EXPECT_EQ(r.counts.failed, reflective_pixels);
}

// Every pixel whose mirror ray really hits `object` must fail and carry no reflection.
void expect_reflections_of_object_fail(const SyntheticScene& scene, const SsrResult& r, int object, int at_least) {
  int checked = 0;
  for (std::size_t i = 0; i < r.mask.size(); ++i) {
    if (!reflective(r.cpu, i) || !is_object(scene, mirror_hit(scene, r, i), object)) continue;
    ++checked;
    EXPECT_EQ(r.mask[i], 1) << "pixel " << i << " reflects an object SSR cannot see\n" << ascii_map(r);
    EXPECT_EQ(r.reflection[i], vec4(0.0f));
  }
  EXPECT_GE(checked, at_least) << "the scene must make many mirror rays reach the object";
}

TEST_P(SsrPassTest, ObjectBehindTheCameraSeenInAMirrorWallFails) {
  SyntheticScene scene;
  scene.add_floor(50.0f, kFloorLit, 0.0f);
  scene.add_quad(2, vec3(-8.0f, 0.0f, -4.0f), vec3(8.0f, 8.0f, -4.0f), vec3(0.0f, 0.0f, 1.0f), kFloorLit, 1.0f);
  const int box = scene.add_box(vec3(-1.5f, 0.0f, 2.0f), vec3(1.5f, 3.0f, 3.0f), kBoxLit, 0.0f);
  SyntheticCamera camera;
  camera.position = vec3(0.0f, 1.5f, 0.0f);
  camera.target = vec3(0.0f, 1.5f, -4.0f);
  const SsrResult r = run_ssr(scene, camera, GetParam());
  for (std::size_t i = 0; i < r.mask.size(); ++i)
    ASSERT_FALSE(r.cpu.quad[i] >= 0 && scene.quads[static_cast<std::size_t>(r.cpu.quad[i])].object == box)
        << "the box must be behind the camera";
  expect_reflections_of_object_fail(scene, r, box, 100);
}

TEST_P(SsrPassTest, ObjectAboveTheViewSeenInTheFloorFails) {
  SyntheticScene scene;
  scene.add_floor(50.0f, kFloorLit, 1.0f);
  const int box = scene.add_box(vec3(-2.0f, 4.0f, -6.0f), vec3(2.0f, 5.0f, -3.0f), kBoxLit, 0.0f);
  SyntheticCamera camera;
  camera.position = vec3(0.0f, 2.0f, 0.0f);
  camera.target = vec3(0.0f, 0.0f, -3.0f);
  const SsrResult r = run_ssr(scene, camera, GetParam());
  for (std::size_t i = 0; i < r.mask.size(); ++i)
    ASSERT_FALSE(r.cpu.quad[i] >= 0 && scene.quads[static_cast<std::size_t>(r.cpu.quad[i])].object == box)
        << "the box must be off screen";
  expect_reflections_of_object_fail(scene, r, box, 100);
}

// A one-sided wall seen from its back: the mirror rays reach its back side and must fail. With the
// normal turned to face the camera the same rays are trusted hits (the control).
TEST_P(SsrPassTest, ReflectedBackFaceFailsAndTheFrontFaceIsHit) {
  for (const float facing : {-1.0f, 1.0f}) {
    SyntheticScene scene;
    scene.add_floor(50.0f, kFloorLit, 1.0f);
    const int wall = scene.add_quad(2, vec3(-1.5f, 0.0f, -2.0f), vec3(1.5f, 2.0f, -2.0f), vec3(0.0f, 0.0f, facing),
                                    kBoxLit, 0.0f);
    SyntheticCamera camera;
    camera.position = vec3(0.0f, 1.4f, 3.0f);
    camera.target = vec3(0.0f, 0.5f, -1.0f);
    const SsrResult r = run_ssr(scene, camera, GetParam());
    if (facing < 0.0f) {
      expect_reflections_of_object_fail(scene, r, wall, 40);
      continue;
    }
    int hits = 0;
    for (std::size_t i = 0; i < r.mask.size(); ++i) {
      const auto hit = mirror_hit(scene, r, i);
      if (!reflective(r.cpu, i) || !is_object(scene, hit, wall) || !clearly_on_screen(scene, r, *hit, GetParam()))
        continue;
      EXPECT_EQ(r.mask[i], 0) << "front face must be hit at pixel " << i << "\n" << ascii_map(r);
      hits += r.mask[i] == 0;
    }
    EXPECT_GE(hits, 40);
  }
}

// A box cut by the left screen border: hits in the edge fade band lose confidence and fail; without
// the fade the same pixels are hits, and the fade never turns a failure into a hit.
TEST_P(SsrPassTest, HitsInTheScreenEdgeBandFailOnlyWithTheEdgeFade) {
  SyntheticScene scene;
  scene.add_floor(50.0f, kFloorLit, 1.0f);
  const int box = scene.add_box(vec3(-4.5f, 0.0f, -2.5f), vec3(-2.2f, 1.6f, -1.5f), kBoxLit, 0.0f);
  SyntheticCamera camera;
  camera.position = vec3(0.0f, 1.4f, 3.0f);
  camera.target = vec3(0.0f, 0.5f, -1.0f);
  SsrSettings with_fade = GetParam();
  with_fade.edge_fade = 0.1f;  // a band of 4.8 pixels
  SsrSettings without_fade = GetParam();
  without_fade.edge_fade = 0.0f;
  const SsrResult faded = run_ssr(scene, camera, with_fade);
  const SsrResult plain = run_ssr(scene, camera, without_fade);
  const float band = with_fade.edge_fade * kHeight;
  int in_band = 0;
  for (std::size_t i = 0; i < faded.mask.size(); ++i) {
    if (!reflective(faded.cpu, i)) continue;
    EXPECT_TRUE(faded.mask[i] == 1 || plain.mask[i] == 0) << "the edge fade created a hit at pixel " << i;
    const auto hit = mirror_hit(scene, faded, i);
    if (!is_object(scene, hit, box) || plain.mask[i] != 0) continue;
    // Where the fade term alone is below the threshold the hit must fail.
    const float column = std::floor(testing::project_to_pixels(faded.constants, hit->position).x) + 0.5f;
    const float x = glm::clamp(column / band, 0.0f, 1.0f);
    if (x * x * (3.0f - 2.0f * x) < 0.5f * with_fade.confidence_threshold) {
      ++in_band;
      EXPECT_EQ(faded.mask[i], 1) << "hit " << column << " px from the border must fail at pixel " << i;
    }
  }
  EXPECT_GE(in_band, 5) << "the scene must put hits into the edge band";
}

// Running out of steps or of distance fails: with 3 steps only hits a few pixels away survive, and
// with max_distance 1 only hits within about 1 world unit.
TEST_F(SsrPassLimits, MaxStepsAndMaxDistanceBoundTheMarch) {
  const FloorAndBox setup;
  SsrSettings few_steps;
  few_steps.max_steps = 3;
  SsrSettings short_rays = few_steps;
  short_rays.max_steps = 256;
  short_rays.max_distance = 1.0f;
  const SsrResult full = run_ssr(setup.scene, setup.camera, SsrSettings{});
  const SsrResult stepped = run_ssr(setup.scene, setup.camera, few_steps);
  const SsrResult shortened = run_ssr(setup.scene, setup.camera, short_rays);
  int stepped_hits = 0, long_failed = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = full.cpu.index(x, y);
      if (!reflective(full.cpu, i)) continue;
      const auto hit = mirror_hit(setup.scene, full, i);
      if (stepped.mask[i] == 0) {
        ++stepped_hits;
        ASSERT_TRUE(hit.has_value());
        const vec2 q = testing::project_to_pixels(full.constants, hit->position);
        const vec2 origin(float(x) + 0.5f, float(y) + 0.5f);
        EXPECT_LE(std::max(std::abs(q.x - origin.x), std::abs(q.y - origin.y)), 5.0f)
            << "a 3-step march hit something far away at " << x << "," << y;
      }
      if (shortened.mask[i] == 0) {
        EXPECT_LE(shortened.reflection[i].w, 1.1f) << x << "," << y;
      }
      if (is_object(setup.scene, hit, setup.box) && hit->t > 1.3f) {
        ++long_failed;
        EXPECT_EQ(shortened.mask[i], 1) << "a ray longer than max_distance was trusted at " << x << "," << y;
      }
    }
  }
  EXPECT_LT(stepped_hits, static_cast<int>(full.counts.reflective - full.counts.failed));
  EXPECT_GT(long_failed, 40);
  EXPECT_EQ(stepped.counts.failed, stepped.counts.reflective - static_cast<std::uint32_t>(stepped_hits));
}

SsrSettings thin_settings() {
  SsrSettings s;
  s.thickness = 0.002f;
  return s;
}
SsrSettings walk_behind_settings() {
  SsrSettings s;
  s.empty_behind = s.thickness;  // every hidden ray walks on
  return s;
}

INSTANTIATE_TEST_SUITE_P(Variants, SsrPassTest,
                         ::testing::Values(SsrSettings{}, thin_settings(), walk_behind_settings()),
                         [](const auto& param_info) {
                           const std::size_t i = param_info.index;
                           return std::string(i == 0 ? "defaults" : i == 1 ? "thin" : "walk_behind_hidden");
                         });



TEST_F(SsrPassErrors, InvalidSettingsNameTheField) {
  SsrSettings s;
  s.max_steps = 0;
  EXPECT_NE(glint::testing::error_of([&] { validate(s); }).find("max_steps"), std::string::npos);
  s = {};
  s.confidence_threshold = 1.5f;
  EXPECT_NE(glint::testing::error_of([&] { validate(s); }).find("confidence_threshold"), std::string::npos);
  s = {};
  s.thickness = 0.0f;
  EXPECT_NE(glint::testing::error_of([&] { SsrPass pass(8, 8, s); }).find("thickness"), std::string::npos);
  EXPECT_NE(glint::testing::error_of([] { SsrPass pass(0, 8); }).find("invalid size"), std::string::npos);
}

TEST_F(SsrPassErrors, InputOfTheWrongSizeOrFormatIsAnError) {
  const FloorAndBox setup;
  const testing::GpuGBuffer gpu = testing::synthetic_frame(setup.scene, setup.camera, kWidth, kHeight).gpu;
  SsrPass pass(kWidth, kHeight);
  const GlTexture small = create_texture_2d(GL_RGBA16F, 32, 32);
  SsrInputs inputs{gpu.albedo_reflectivity.id(), gpu.world_position.id(), gpu.world_normal.id(), small.id(),
                   gpu.frame_constants.id()};
  EXPECT_NE(glint::testing::error_of([&] { pass.run(inputs); }).find("input 'lit' is 32x32, the pass is 64x48"),
            std::string::npos);
  inputs.lit = gpu.world_position.id();  // RGBA32F where RGBA16F is expected
  EXPECT_NE(glint::testing::error_of([&] { pass.run(inputs); }).find("'lit' has internal format"), std::string::npos);
  inputs.lit = gpu.lit.id();
  inputs.frame_constants = 0;
  EXPECT_NE(glint::testing::error_of([&] { pass.run(inputs); }).find("frame_constants"), std::string::npos);
}

}  // namespace
}  // namespace glint::render
