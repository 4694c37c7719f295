// Screen-space reach (render/screen_space_reach.h) on scenes whose answer is known: a mirror wall
// that reflects only a wall behind the camera (everything off screen), a mirror floor before a wall
// in view (on screen), a beam hiding part of that wall from the camera (occluded), and a brute-force
// oracle that asks the ray tracer whether the camera sees each reflected hit.
#include "backends/registry.h"
#include "render/frame_constants.h"
#include "render/ray_origin_offset.h"
#include "render/screen_space_reach.h"
#include "render/raster_test_scene.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace glint::render {
namespace {

using glint::testing::add_material;
using glint::testing::add_quad;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// A G-buffer ray cast through every pixel centre with the tracer itself: positions, the meshes'
// normals, reflectivity, visibility ids.
struct CastGBuffer {
  ImageRgbaF position{kWidth, kHeight, vec4(0.0f)};
  ImageRgbaF normal{kWidth, kHeight, vec4(0.0f)};
  ImageRgbaF albedo{kWidth, kHeight, vec4(0.0f)};
  ImageRgbaF ids{kWidth, kHeight, vec4(0.0f)};
  ReachGBuffer view(bool with_ids) const { return {position, normal, albedo, with_ids ? &ids : nullptr}; }
};

struct CastScene {
  Scene scene;
  FrameConstants frame;
  std::unique_ptr<rt::RayTracer> tracer;
  CastGBuffer gbuffer;
  float offset = 0.0f;
};

CastScene cast(Scene scene, const FrameState& state) {
  CastScene s{std::move(scene), {}, backends::make_ray_tracer("cpu"), {}, 0.0f};
  s.frame = make_frame_constants(s.scene, s.scene.world_bounds(), state, kWidth, kHeight);
  s.tracer->build(s.scene, {});
  s.offset = ray_origin_offset(1e-4f, s.scene.world_bounds());
  const vec3 camera = vec3(s.frame.camera_position);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      accel::Ray ray;
      ray.origin = camera;
      ray.direction = glint::testing::pixel_ray(s.frame, x, y);
      accel::Hit hit;
      s.tracer->trace_closest({&ray, 1}, {&hit, 1});
      if (!hit.valid()) continue;
      const Instance& instance = s.scene.instances[hit.instance];
      const Mesh& mesh = s.scene.meshes[instance.mesh];
      const vec3 authored = mesh.normals[mesh.indices[3 * hit.prim]];
      const vec3 normal = glm::normalize(vec3(instance.transform * vec4(authored, 0.0f)));
      s.gbuffer.position.at(x, y) = vec4(camera + hit.t * ray.direction, 1.0f);
      s.gbuffer.normal.at(x, y) = vec4(normal, 0.0f);
      s.gbuffer.albedo.at(x, y) = vec4(0.5f, 0.5f, 0.5f, s.scene.materials[mesh.material].reflectivity);
      s.gbuffer.ids.at(x, y) = vec4(static_cast<float>(hit.instance) + 1.0f, static_cast<float>(hit.prim), 0.0f, 1.0f);
    }
  return s;
}

ScreenSpaceReach measure(const CastScene& s, bool with_ids = false) {
  return measure_screen_space_reach(s.scene, *s.tracer, s.gbuffer.view(with_ids), s.frame, s.offset);
}

// The oracle: the same mirror rays, then whether the hit lies in the view frustum (the full view
// projection, not the camera-relative one) and whether a ray from the camera to it meets anything first.
std::vector<ReachClass> brute_force(const CastScene& s) {
  std::vector<ReachClass> classes(s.gbuffer.position.pixels.size(), ReachClass::not_reflective);
  const vec3 camera = vec3(s.frame.camera_position);
  for (std::size_t i = 0; i < classes.size(); ++i) {
    const vec4 p = s.gbuffer.position.pixels[i];
    if (p.w == 0.0f || s.gbuffer.albedo.pixels[i].w <= 0.0f) continue;
    vec3 n = vec3(s.gbuffer.normal.pixels[i]);
    const vec3 v = glm::normalize(camera - vec3(p));
    if (glm::dot(n, v) < 0.0f) n = -n;
    accel::Ray ray;
    ray.origin = vec3(p) + s.offset * n;
    ray.direction = glm::reflect(-v, n);
    accel::Hit hit;
    s.tracer->trace_closest({&ray, 1}, {&hit, 1});
    if (!hit.valid()) {
      classes[i] = ReachClass::miss;
      continue;
    }
    const vec3 point = ray.origin + hit.t * ray.direction;
    const vec4 clip = s.frame.view_projection * vec4(point, 1.0f);
    if (!(clip.w > 0.0f && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w && std::abs(clip.z) <= clip.w)) {
      classes[i] = ReachClass::off_screen;
      continue;
    }
    accel::Ray look;
    look.origin = camera;
    look.direction = point - camera;  // t = 1 at the hit
    accel::Hit seen;
    s.tracer->trace_closest({&look, 1}, {&seen, 1});
    const bool same = seen.valid() && seen.instance == hit.instance && std::abs(seen.t - 1.0f) < 1e-3f;
    classes[i] = same ? ReachClass::on_screen : ReachClass::occluded;
  }
  return classes;
}

std::size_t disagreements(const std::vector<ReachClass>& a, const std::vector<ReachClass>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) n += a[i] != b[i] ? 1 : 0;
  return n;
}

// A mirror wall at z = -4 facing the camera at z = 6, and a wide matte wall at z = 12 behind the
// camera facing it: every mirror pixel reflects the wall behind the camera.
Scene mirror_wall_and_wall_behind_camera() {
  Scene scene = glint::testing::make_empty_test_scene(vec3(0.0f, 6.0f, 0.0f));
  const std::uint32_t mirror = add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t matte = add_material(scene, vec3(0.7f));
  add_quad(scene, vec3(-3.0f, 0.0f, -4.0f), vec3(6.0f, 0.0f, 0.0f), vec3(0.0f, 3.0f, 0.0f), mirror);
  add_quad(scene, vec3(200.0f, -200.0f, 12.0f), vec3(-400.0f, 0.0f, 0.0f), vec3(0.0f, 400.0f, 0.0f), matte);
  return scene;
}

FrameState facing_the_mirror_wall() {
  return glint::testing::look_at(vec3(0.0f, 1.5f, 6.0f), vec3(0.0f, 1.5f, -4.0f), vec3(0.0f, 6.0f, 0.0f));
}

// A box of six outward-facing sides.
void add_box(Scene& scene, vec3 min, vec3 max) {
  const std::uint32_t stone = add_material(scene, vec3(0.6f));
  const vec3 d = max - min;
  add_quad(scene, vec3(min.x, min.y, max.z), vec3(d.x, 0, 0), vec3(0, d.y, 0), stone);   // +z
  add_quad(scene, vec3(max.x, min.y, min.z), vec3(-d.x, 0, 0), vec3(0, d.y, 0), stone);  // -z
  add_quad(scene, vec3(max.x, min.y, max.z), vec3(0, 0, -d.z), vec3(0, d.y, 0), stone);  // +x
  add_quad(scene, vec3(min.x, min.y, min.z), vec3(0, 0, d.z), vec3(0, d.y, 0), stone);   // -x
  add_quad(scene, vec3(min.x, max.y, max.z), vec3(d.x, 0, 0), vec3(0, 0, -d.z), stone);  // +y
  add_quad(scene, vec3(min.x, min.y, min.z), vec3(d.x, 0, 0), vec3(0, 0, d.z), stone);   // -y
}

// The mirror floor before the wall, and a beam floating between them: from the camera above it
// hides the wall's foot, which the mirror, looking from below, still shows (and the beam's underside,
// which the camera never sees).
Scene floor_wall_and_beam() {
  Scene scene = glint::testing::mirror_floor_with_wall(-4.0f, vec2(8.0f, 2.0f));
  add_box(scene, vec3(-1.0f, 0.6f, -2.0f), vec3(1.0f, 0.9f, -1.6f));
  return scene;
}

TEST(ScreenSpaceReach, AMirrorReflectingOnlyAWallBehindTheCameraIsAllOffScreen) {
  const CastScene s = cast(mirror_wall_and_wall_behind_camera(), facing_the_mirror_wall());
  const ScreenSpaceReach reach = measure(s);
  ASSERT_GT(reach.reflective, 300u);
  EXPECT_EQ(reach.off_screen, reach.reflective);
  EXPECT_EQ(reach.must_trace(), reach.reflective);
  EXPECT_DOUBLE_EQ(reach.percent(reach.off_screen), 100.0);
  EXPECT_EQ(disagreements(reach.classes, brute_force(s)), 0u);
  // The wall behind the camera is 16 to 17 units from the mirror: beyond a fade ending at 10 it shows
  // in no picture, before one ending at 100 in every one.
  EXPECT_EQ(reach.must_trace_within_fade, reach.reflective);  // no fade
  const ReachGBuffer g = s.gbuffer.view(false);
  EXPECT_EQ(measure_screen_space_reach(s.scene, *s.tracer, g, s.frame, s.offset, 10.0f).must_trace_within_fade, 0u);
  EXPECT_EQ(measure_screen_space_reach(s.scene, *s.tracer, g, s.frame, s.offset, 100.0f).must_trace_within_fade,
            reach.reflective);
}

TEST(ScreenSpaceReach, AMirrorFloorBeforeAWallInViewReachesTheWallOnScreen) {
  const CastScene s = cast(glint::testing::mirror_floor_with_wall(-4.0f, vec2(8.0f, 2.0f)),
                       glint::testing::camera_looking_down_the_floor());
  for (const bool with_ids : {false, true}) {
    const ScreenSpaceReach reach = measure(s, with_ids);
    ASSERT_GT(reach.reflective, 1000u);
    EXPECT_GT(reach.on_screen, reach.reflective / 10) << "with ids " << with_ids;
    EXPECT_EQ(reach.occluded, 0u) << "with ids " << with_ids;
    EXPECT_GT(reach.miss, 0u);
    EXPECT_EQ(reach.on_screen + reach.off_screen + reach.occluded + reach.miss, reach.reflective);
    // Every miss goes up past the wall; those near the top of the picture leave the view above it.
    EXPECT_LE(reach.miss_leaving_view, reach.miss);
    EXPECT_EQ(disagreements(reach.classes, brute_force(s)), 0u) << "with ids " << with_ids;
  }
}

TEST(ScreenSpaceReach, ABeamHidingPartOfTheWallMakesItsReflectionOccluded) {
  Scene scene = floor_wall_and_beam();
  const CastScene s = cast(std::move(scene), glint::testing::camera_looking_down_the_floor());
  const ScreenSpaceReach reach = measure(s);
  const std::vector<ReachClass> oracle = brute_force(s);
  std::size_t oracle_occluded = 0;
  for (const ReachClass c : oracle) oracle_occluded += c == ReachClass::occluded ? 1 : 0;
  RecordProperty("reflective", std::to_string(reach.reflective));
  RecordProperty("occluded", std::to_string(reach.occluded));
  RecordProperty("oracle_occluded", std::to_string(oracle_occluded));
  RecordProperty("disagreements", std::to_string(disagreements(reach.classes, oracle)));
  ASSERT_GT(oracle_occluded, 20u);
  EXPECT_GT(reach.occluded, oracle_occluded / 2);
  EXPECT_LE(reach.occluded, oracle_occluded);  // the one-pixel margin only ever counts more as on screen
  EXPECT_GT(reach.on_screen, reach.reflective / 10);
  // Disagreements only at silhouettes (the one-pixel margin): a few percent.
  EXPECT_LE(disagreements(reach.classes, oracle), reach.reflective / 50);
}

TEST(ScreenSpaceReach, AScaledAndFarMovedSceneClassifiesTheSamePixels) {
  Scene scene = floor_wall_and_beam();
  const ScreenSpaceReach base = measure(cast(scene, glint::testing::camera_looking_down_the_floor()));
  const float scale = 1000.0f;
  const vec3 shift(3.0e5f, 1.0e5f, -2.0e5f);
  const mat4 to_far = glm::translate(mat4(1.0f), shift) * glm::scale(mat4(1.0f), vec3(scale));
  for (Instance& instance : scene.instances) instance.transform = to_far * instance.transform;
  scene.light.position = vec3(to_far * vec4(scene.light.position, 1.0f));
  FrameState state = glint::testing::camera_looking_down_the_floor();
  state.camera.position = vec3(to_far * vec4(state.camera.position, 1.0f));
  state.camera.target = vec3(to_far * vec4(state.camera.target, 1.0f));
  state.light_position = vec3(to_far * vec4(state.light_position, 1.0f));
  const ScreenSpaceReach far = measure(cast(std::move(scene), state));
  EXPECT_NEAR(static_cast<double>(far.reflective), static_cast<double>(base.reflective),
              static_cast<double>(base.reflective) / 200.0);
  EXPECT_LE(disagreements(far.classes, base.classes), base.reflective / 100);
  EXPECT_GT(far.occluded, 0u);
}

TEST(ScreenSpaceReach, GBufferImagesOfDifferentSizesAreAnError) {
  const CastScene s = cast(mirror_wall_and_wall_behind_camera(), facing_the_mirror_wall());
  const ImageRgbaF small(8, 8, vec4(0.0f));
  const ReachGBuffer g{s.gbuffer.position, small, s.gbuffer.albedo, nullptr};
  EXPECT_THROW((void)measure_screen_space_reach(s.scene, *s.tracer, g, s.frame, s.offset), Error);
}

}  // namespace
}  // namespace glint::render
