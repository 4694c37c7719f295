// The default camera and light of a scene without a walkthrough (a bare OBJ or glTF): the camera in
// free space seeing the geometry, the light outside solid objects lighting what the camera sees, for
// an object on a floor, a lone triangle and a closed room, at their size and scaled by 1000 and moved
// far from the origin.
#include "core/log.h"
#include "scene/camera_path.h"
#include "scene/default_walkthrough.h"
#include "scene/mesh_ops.h"
#include "scene/scene_ray_probe.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace glint {
namespace {

// Appends the quad centre +- u +- v, front side towards cross(u, v).
void add_quad(Mesh& mesh, vec3 centre, vec3 u, vec3 v) {
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (const vec3& corner : {centre - u - v, centre + u - v, centre + u + v, centre - u + v}) mesh.positions.push_back(corner);
  for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
}

// An axis-aligned box; its faces point outwards (a solid) or inwards (a room).
void add_box(Mesh& mesh, vec3 lo, vec3 hi, bool facing_inwards) {
  const vec3 c = 0.5f * (lo + hi), h = 0.5f * (hi - lo);
  const vec3 x(h.x, 0, 0), y(0, h.y, 0), z(0, 0, h.z);
  // (u, v) with cross(u, v) along the outward normal of the face at c + offset.
  const struct {
    vec3 offset, u, v;
  } faces[] = {{x, y, z}, {-x, z, y}, {y, z, x}, {-y, x, z}, {z, x, y}, {-z, y, x}};
  for (const auto& face : faces) {
    if (facing_inwards) add_quad(mesh, c + face.offset, face.v, face.u);
    else add_quad(mesh, c + face.offset, face.u, face.v);
  }
}

struct TestScene {
  Scene scene;
  mat4 placement{1.0f};  // where the test put the geometry: world = placement * model
  std::vector<Aabb> solids;  // model-space boxes a camera or light must stay out of
  Aabb room;                 // model-space box both must stay inside (empty: none)
};

TestScene make_scene(Mesh mesh, const mat4& placement) {
  TestScene t;
  mesh.name = "geometry";
  compute_flat_normals(mesh);
  t.scene.name = "test";
  t.scene.source = "test";
  t.scene.materials.push_back(Material{});
  t.scene.meshes.push_back(std::move(mesh));
  t.scene.instances.push_back({"geometry", 0, placement});
  t.placement = placement;
  return t;
}

TestScene plane_and_cube(const mat4& placement) {
  Mesh mesh;
  add_quad(mesh, vec3(0, 0, 0), vec3(0, 0, 5), vec3(5, 0, 0));  // a 10 x 10 floor facing up
  add_box(mesh, vec3(-0.5f, 0, -0.5f), vec3(0.5f, 1, 0.5f), false);
  TestScene t = make_scene(mesh, placement);
  t.solids.push_back(Aabb{vec3(-0.5f, 0, -0.5f), vec3(0.5f, 1, 0.5f)});
  return t;
}

TestScene single_triangle(const mat4& placement) {
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(0, 0, 2), vec3(3, 0, 0)};  // flat on y = 0, facing up
  mesh.indices = {0, 1, 2};
  return make_scene(mesh, placement);
}

TestScene closed_room(const mat4& placement) {
  Mesh mesh;
  add_box(mesh, vec3(-4, 0, -3), vec3(4, 3, 3), true);
  TestScene t = make_scene(mesh, placement);
  t.room = Aabb{vec3(-4, 0, -3), vec3(4, 3, 3)};
  return t;
}

// Scaled by 1000 and moved to (20000, 5000, -30000): no length in the placement may be absolute.
mat4 far_and_large() {
  return glm::scale(glm::translate(mat4(1.0f), vec3(20000, 5000, -30000)), vec3(1000.0f));
}

vec3 to_model(const TestScene& t, vec3 world) { return vec3(glm::inverse(t.placement) * vec4(world, 1.0f)); }

bool strictly_inside(const Aabb& box, vec3 p) {
  return glm::all(glm::greaterThan(p, box.min)) && glm::all(glm::lessThan(p, box.max));
}

// Rays through the centre and the corners of the middle of the image (+-half of the field of view).
std::vector<vec3> view_directions(const CameraState& camera) {
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const vec3 up = glm::cross(right, forward);
  const float half = std::tan(glm::radians(camera.fov_y_degrees) / 2.0f) * 0.5f;
  std::vector<vec3> directions = {forward};
  for (const float x : {-1.0f, 1.0f})
    for (const float y : {-1.0f, 1.0f}) directions.push_back(glm::normalize(forward + half * (16.0f / 9.0f * x * right + y * up)));
  return directions;
}

struct Checked {
  int frames = 0;
  int centre_hits = 0;
  int view_rays = 0;
  int view_hits = 0;
  int lit_centres = 0;
};

// Samples the walkthrough at 16 frames and checks every rule that must always hold; returns counts
// for the rules that must hold "mostly".
Checked check_walkthrough(const TestScene& t) {
  const WalkthroughAnimation animation(t.scene);  // the walkthrough is valid
  const SceneRayProbe probe(t.scene);
  Checked checked;
  // Positions alone (no rays) at 100 frames: a swept light crosses a solid only for a few of them.
  for (int i = 0; i < 100; ++i) {
    const FrameState state = animation.at(i * (animation.frame_count() - 1) / 99);
    for (const Aabb& solid : t.solids) {
      EXPECT_FALSE(solid.contains(to_model(t, state.camera.position))) << "frame " << state.frame << ": camera in a solid";
      EXPECT_FALSE(solid.contains(to_model(t, state.light_position))) << "frame " << state.frame << ": light in a solid";
    }
  }
  for (int i = 0; i < 16; ++i) {
    const FrameState state = animation.at(i * (animation.frame_count() - 1) / 15);
    const vec3 camera = to_model(t, state.camera.position), light = to_model(t, state.light_position);
    for (const Aabb& solid : t.solids) {
      EXPECT_FALSE(solid.contains(camera)) << "frame " << state.frame << ": the camera is inside a solid";
      EXPECT_FALSE(solid.contains(light)) << "frame " << state.frame << ": the light is inside a solid";
    }
    if (!t.room.empty()) {
      EXPECT_TRUE(strictly_inside(t.room, camera)) << "frame " << state.frame << ": the camera is outside the room";
      EXPECT_TRUE(strictly_inside(t.room, light)) << "frame " << state.frame << ": the light is outside the room";
    }
    ++checked.frames;
    const std::vector<vec3> directions = view_directions(state.camera);
    std::vector<accel::Ray> rays;
    for (const vec3& d : directions) rays.push_back({state.camera.position, 0.0f, d, accel::kInfinity});
    const std::vector<ProbeHit> hits = probe.closest(rays);
    for (const ProbeHit& hit : hits) checked.view_hits += hit.hit ? 1 : 0;
    checked.view_rays += static_cast<int>(hits.size());
    if (!hits[0].hit) continue;
    ++checked.centre_hits;
    // The light reaches the point in the middle of the image: the same side, nothing in between.
    const ProbeHit& seen = hits[0];
    const bool same_side = glm::dot(seen.normal, state.camera.position - seen.point) *
                               glm::dot(seen.normal, state.light_position - seen.point) > 0.0f;
    const vec3 to_point = seen.point - state.light_position;
    const std::vector<ProbeHit> shadow =
        probe.closest(std::vector<accel::Ray>{{state.light_position, 0.0f, glm::normalize(to_point), accel::kInfinity}});
    const bool unoccluded = shadow[0].hit && (shadow[0].triangle == seen.triangle ||
                                              shadow[0].distance >= glm::length(to_point) * (1.0f - 1e-3f));
    if (same_side && unoccluded) ++checked.lit_centres;
  }
  return checked;
}

void expect_plane_and_cube_looks_right(const mat4& placement) {
  TestScene t = plane_and_cube(placement);
  assign_default_walkthrough(t.scene);
  const Checked c = check_walkthrough(t);
  EXPECT_EQ(c.centre_hits, c.frames) << "the middle of every frame shows the floor or the cube";
  EXPECT_GT(c.view_hits, c.view_rays / 2) << "most of the frame shows geometry";
  EXPECT_GE(c.lit_centres, c.frames * 3 / 4) << "the light reaches what the camera looks at";
}

TEST(DefaultWalkthrough, PlaneAndCubeKeepsCameraAndLightOutOfTheCube) { expect_plane_and_cube_looks_right(mat4(1.0f)); }

TEST(DefaultWalkthrough, PlaneAndCubeScaledAndFarFromTheOrigin) { expect_plane_and_cube_looks_right(far_and_large()); }

void expect_single_triangle_is_seen_from_above(const mat4& placement) {
  TestScene t = single_triangle(placement);
  assign_default_walkthrough(t.scene);
  const Checked c = check_walkthrough(t);
  EXPECT_EQ(c.centre_hits, c.frames) << "every frame looks at the triangle, not along its plane";
  EXPECT_EQ(c.lit_centres, c.centre_hits) << "the light is on the side the camera sees";
  const WalkthroughAnimation animation(t.scene);
  for (const int frame : {0, animation.frame_count() / 2})
    EXPECT_GT(to_model(t, animation.at(frame).camera.position).y, 0.1f) << "the camera is above the triangle's plane";
}

TEST(DefaultWalkthrough, SingleTriangleIsSeenFromAboveItsPlane) { expect_single_triangle_is_seen_from_above(mat4(1.0f)); }

TEST(DefaultWalkthrough, SingleTriangleScaledAndFarFromTheOrigin) { expect_single_triangle_is_seen_from_above(far_and_large()); }

void expect_room_is_seen_from_inside(const mat4& placement) {
  TestScene t = closed_room(placement);
  assign_default_walkthrough(t.scene);
  const Checked c = check_walkthrough(t);  // camera and light strictly inside the room
  EXPECT_EQ(c.view_hits, c.view_rays) << "inside a closed room every ray meets a wall";
  EXPECT_EQ(c.lit_centres, c.frames) << "the light reaches what the camera looks at";
}

TEST(DefaultWalkthrough, ClosedRoomHasCameraAndLightInside) { expect_room_is_seen_from_inside(mat4(1.0f)); }

TEST(DefaultWalkthrough, ClosedRoomScaledAndFarFromTheOrigin) { expect_room_is_seen_from_inside(far_and_large()); }

TEST(DefaultWalkthrough, ScalingAndMovingTheSceneMovesTheWalkthroughWithIt) {
  TestScene near = plane_and_cube(mat4(1.0f));
  TestScene far = plane_and_cube(far_and_large());
  assign_default_walkthrough(near.scene);
  assign_default_walkthrough(far.scene);
  ASSERT_EQ(near.scene.walkthrough.camera.points.size(), far.scene.walkthrough.camera.points.size());
  for (std::size_t i = 0; i < near.scene.walkthrough.camera.points.size(); ++i)
    EXPECT_LT(glm::distance(near.scene.walkthrough.camera.points[i], to_model(far, far.scene.walkthrough.camera.points[i])),
              0.05f)
        << "camera point " << i;
  EXPECT_LT(glm::distance(near.scene.light.position, to_model(far, far.scene.light.position)), 0.05f);
}

// Copies of one triangle in one place would make every probe ray test all of them (a glTF whose node
// graph lists a child twice at 16 levels took a minute to load): the probe keeps one.
TEST(SceneRayProbe, KeepsOneCopyOfTrianglesInTheSamePlace) {
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 0, 1)};
  for (int i = 0; i < 1000; ++i) mesh.indices.insert(mesh.indices.end(), {0, 2, 1});
  mesh.indices.insert(mesh.indices.end(), {2, 1, 0, 1, 0, 2});  // the same winding from other corners
  mesh.indices.insert(mesh.indices.end(), {0, 1, 2});           // the other side: another triangle
  TestScene t = make_scene(mesh, mat4(1.0f));
  for (int i = 0; i < 500; ++i) t.scene.instances.push_back({"copy", 0, mat4(1.0f)});
  t.scene.instances.push_back({"moved", 0, glm::translate(mat4(1.0f), vec3(0, 1, 0))});
  const SceneRayProbe probe(t.scene);
  EXPECT_EQ(probe.triangle_count(), 4u) << "two sides, in two places";
  const std::vector<ProbeHit> hits =
      probe.closest(std::vector<accel::Ray>{{vec3(0.2f, 0.5f, 0.2f), 0.0f, vec3(0, -1, 0), accel::kInfinity}});
  ASSERT_TRUE(hits[0].hit);
  EXPECT_NEAR(hits[0].distance, 0.5f, 1e-6f);
}

// Distinct triangles that all overlap (each crosses the whole scene) defeat any BVH: probing them
// with 10^5 rays would take minutes for a few 10^4 of them, so the placement falls back to the bounds.
TEST(DefaultWalkthrough, GeometryOverlappingItselfEverywhereFallsBackToTheBoundsWithAWarning) {
  Mesh mesh;
  for (int i = 0; i < 4000; ++i) {
    const float angle = 0.0015f * static_cast<float>(i);
    const vec3 along(std::cos(angle), 0.0f, std::sin(angle));
    const auto first = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {-10.0f * along, 10.0f * along, vec3(0, 1, 0)});
    mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2});
  }
  TestScene t = make_scene(mesh, mat4(1.0f));
  ScopedLogCapture log;
  assign_default_walkthrough(t.scene);
  EXPECT_EQ(log.count_warnings("overlaps itself so much"), 1);
  EXPECT_NO_THROW(WalkthroughAnimation{t.scene});
  EXPECT_EQ(t.scene.walkthrough.light.points.size(), 2u) << "the classic sweep";
}

}  // namespace
}  // namespace glint
