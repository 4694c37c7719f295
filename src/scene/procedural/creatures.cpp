#include "scene/procedural/creatures.h"

#include "scene/procedural/isosurface.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace glint::procedural {
namespace {

// Rotation (as ellipsoid axes) about z by `angle` radians: tilts a shape forward or back.
glm::mat3 rotate_z(float angle) { return glm::mat3(glm::rotate(mat4(1.0f), angle, vec3(0, 0, 1))); }
glm::mat3 rotate_x(float angle) { return glm::mat3(glm::rotate(mat4(1.0f), angle, vec3(1, 0, 0))); }

// Mirrors a left-side (z > 0) point to the right side.
vec3 mirror(vec3 p) { return vec3(p.x, p.y, -p.z); }

}  // namespace

ArmadilloPose armadillo_pose(int index) {
  // Small, fixed variations (no random generator: the table is the design).
  static const ArmadilloPose poses[] = {
      {1.00f, 0.00f, 1.00f, 0.00f, 0.00f},
      {0.92f, 0.18f, 1.15f, 0.12f, 0.04f},
      {1.06f, -0.06f, 0.90f, -0.10f, -0.03f},
      {0.97f, 0.30f, 1.05f, 0.20f, 0.06f},
  };
  return poses[static_cast<std::size_t>(index) % std::size(poses)];
}

DinosaurPose dinosaur_pose(int index) {
  static const DinosaurPose poses[] = {{1.0f, 0.28f, 0.25f}, {0.94f, 0.12f, -0.35f}};
  return poses[static_cast<std::size_t>(index) % std::size(poses)];
}

BlendedShape armadillo_shape(const ArmadilloPose& pose) {
  const float s = pose.scale;
  BlendedShape shape(0.05f * s);
  auto add_ellipsoid = [&](vec3 c, vec3 r, const glm::mat3& axes = glm::mat3(1.0f)) {
    shape.add(ellipsoid(s * c, s * r, axes));
  };
  auto add_capsule = [&](vec3 a, vec3 b, float ra, float rb) { shape.add(capsule(s * a, s * b, s * ra, s * rb)); };
  // Largest parts first, so the early-out in BlendedShape skips small parts most often.
  // Armoured back: an ellipsoid along the hunched spine with raised bands across it.
  const vec3 spine = glm::normalize(vec3(0.38f, 0.92f, 0.0f));
  glm::mat3 shell_axes(spine, vec3(spine.y, -spine.x, 0.0f), vec3(0, 0, 1));
  SdfPrimitive shell = ellipsoid(s * vec3(-0.10f, 1.15f, 0.0f), s * vec3(0.50f, 0.30f, 0.36f), shell_axes);
  shell.ridge_depth = 0.022f * s;
  shell.ridge_period = 0.10f * s;
  shape.add(shell);
  add_ellipsoid({-0.02f, 0.92f, 0.0f}, {0.30f, 0.30f, 0.28f});                  // pelvis
  add_ellipsoid({0.12f, 1.22f, 0.0f}, {0.28f, 0.30f, 0.29f}, rotate_z(-0.45f));  // chest, hunched forward
  add_capsule({0.22f, 1.40f, 0.0f}, {0.38f, 1.52f, 0.0f}, 0.13f, 0.10f);         // neck
  add_ellipsoid({0.46f, 1.55f, 0.0f}, {0.17f, 0.14f, 0.14f});                    // head
  add_capsule({0.56f, 1.54f, 0.0f}, {0.82f, 1.44f + pose.head_tilt, 0.0f}, 0.075f, 0.035f);  // snout
  for (const float side : {1.0f, -1.0f}) {
    auto at = [side](vec3 p) { return side > 0.0f ? p : mirror(p); };
    // Big upright ears, splayed outwards and swept back.
    const float ear = pose.ear_length;
    add_ellipsoid(at({0.38f, 1.66f + 0.11f * ear, 0.11f}), {0.035f, 0.19f * ear, 0.09f},
                  rotate_z(0.3f) * rotate_x(-side * 0.35f));
    // Arms: shoulder, elbow out to the side, hands forward.
    const vec3 shoulder = at({0.22f, 1.36f, 0.25f}), elbow = at({0.34f, 1.10f, 0.37f});
    const vec3 hand = at({0.58f, 1.18f + pose.arm_raise, 0.28f});
    add_capsule(shoulder, elbow, 0.08f, 0.06f);
    add_capsule(elbow, hand, 0.06f, 0.045f);
    add_ellipsoid(hand + at({0.04f, 0.0f, 0.0f}), {0.07f, 0.045f, 0.06f});
    add_capsule(hand + at({0.08f, 0.0f, 0.02f}), hand + at({0.16f, -0.05f, 0.03f}), 0.02f, 0.008f);   // claws
    add_capsule(hand + at({0.08f, 0.0f, -0.02f}), hand + at({0.16f, -0.05f, -0.03f}), 0.02f, 0.008f);
    // Legs: thigh, shin, foot.
    const vec3 hip = at({-0.02f, 0.86f, 0.17f}), knee = at({0.16f, 0.52f, 0.23f}), ankle = at({0.02f, 0.12f, 0.22f});
    add_capsule(hip, knee, 0.13f, 0.09f);
    add_capsule(knee, ankle, 0.085f, 0.06f);
    add_ellipsoid(at({0.10f, 0.05f, 0.22f}), {0.17f, 0.05f, 0.08f});
  }
  // Tail from the pelvis down to the ground.
  add_capsule({-0.28f, 0.78f, 0.0f}, {-0.55f, 0.45f, 0.5f * pose.tail_curl}, 0.10f, 0.07f);
  add_capsule({-0.55f, 0.45f, 0.5f * pose.tail_curl}, {-0.80f, 0.08f, pose.tail_curl}, 0.07f, 0.03f);
  return shape;
}

BlendedShape dinosaur_shape(const DinosaurPose& pose) {
  const float s = pose.scale;
  BlendedShape shape(0.12f * s);
  auto add_ellipsoid = [&](vec3 c, vec3 r, const glm::mat3& axes = glm::mat3(1.0f)) {
    shape.add(ellipsoid(s * c, s * r, axes));
  };
  auto add_capsule = [&](vec3 a, vec3 b, float ra, float rb) { shape.add(capsule(s * a, s * b, s * ra, s * rb)); };
  add_ellipsoid({0.0f, 1.55f, 0.0f}, {0.95f, 0.55f, 0.45f}, rotate_z(0.14f));  // body
  add_ellipsoid({0.55f, 1.65f, 0.0f}, {0.50f, 0.50f, 0.42f});                  // chest
  add_capsule({0.85f, 1.85f, 0.0f}, {1.25f, 2.10f, 0.0f}, 0.32f, 0.26f);       // neck
  add_ellipsoid({1.58f, 2.22f, 0.0f}, {0.46f, 0.24f, 0.23f});                  // skull
  add_ellipsoid({1.78f, 2.13f, 0.0f}, {0.40f, 0.14f, 0.19f});                  // upper jaw
  // Lower jaw hinged below the skull and opened by `jaw_open`.
  const vec3 hinge(1.35f, 2.03f, 0.0f);
  const glm::mat3 jaw_axes = rotate_z(-pose.jaw_open);
  add_ellipsoid(hinge + jaw_axes * vec3(0.38f, -0.05f, 0.0f), {0.40f, 0.07f, 0.16f}, jaw_axes);
  // Tail: three tapering segments, swaying sideways towards the tip.
  const vec3 t0(-0.85f, 1.60f, 0.0f), t1(-1.70f, 1.48f, 0.15f * pose.tail_sway), t2(-2.50f, 1.28f, 0.5f * pose.tail_sway),
      t3(-3.20f, 1.05f, pose.tail_sway);
  add_capsule(t0, t1, 0.42f, 0.27f);
  add_capsule(t1, t2, 0.27f, 0.14f);
  add_capsule(t2, t3, 0.14f, 0.04f);
  for (const float side : {1.0f, -1.0f}) {
    auto at = [side](vec3 p) { return side > 0.0f ? p : mirror(p); };
    add_ellipsoid(at({0.05f, 1.25f, 0.34f}), {0.42f, 0.50f, 0.20f}, rotate_z(-0.26f));  // thigh
    add_capsule(at({0.15f, 0.85f, 0.37f}), at({-0.12f, 0.24f, 0.38f}), 0.14f, 0.09f);    // shin
    add_capsule(at({-0.12f, 0.24f, 0.38f}), at({0.02f, 0.08f, 0.38f}), 0.09f, 0.07f);    // ankle
    add_ellipsoid(at({0.20f, 0.06f, 0.38f}), {0.32f, 0.06f, 0.14f});                    // foot
    add_ellipsoid(at({1.55f, 2.36f, 0.12f}), {0.10f, 0.05f, 0.05f});                    // brow ridge
    // Small two-segment arms.
    const vec3 shoulder = at({0.75f, 1.45f, 0.32f}), elbow = at({0.95f, 1.28f, 0.38f}), hand = at({1.12f, 1.34f, 0.32f});
    add_capsule(shoulder, elbow, 0.07f, 0.05f);
    add_capsule(elbow, hand, 0.05f, 0.035f);
  }
  return shape;
}

CreatureMesh creature_mesh(const BlendedShape& shape, std::size_t target_vertices, const std::string& name,
                           float initial_cell) {
  // The blend swells the union slightly beyond its primitives' spheres; leave room for it.
  Aabb bounds = shape.bounds();
  bounds.extend(bounds.min - vec3(0.05f));
  bounds.extend(bounds.max + vec3(0.05f));
  TargetedMesh result = polygonize_to_vertex_count(shape, bounds, target_vertices, 0.015f, 5, initial_cell);
  result.mesh.name = name;
  return {std::move(result.mesh), result.cell_size};
}

SineDeform dinosaur_deform(const DinosaurPose& pose) {
  SineDeform deform;
  deform.displace_axis = 1;                 // up and down
  deform.wave_axis = 0;                     // travelling along the body (x)
  deform.amplitude = 0.11f * pose.scale;    // ~2 % of the 5.4 m body
  deform.frequency = 2.1f / pose.scale;     // one wavelength ~ 3 m, about half the body
  deform.speed = 2.5f;                      // a slow undulation (one cycle in 2.5 s)
  return deform;
}

}  // namespace glint::procedural
