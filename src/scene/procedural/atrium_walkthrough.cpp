#include "scene/procedural/atrium_walkthrough.h"

#include "scene/procedural/atrium_layout.h"

namespace glint::procedural {
namespace {
constexpr float kEye = 1.7f;         // standing eye height
constexpr float kLookHeight = 1.3f;  // look slightly down, so the floor's reflections are in view
constexpr float kLightHeight = 5.0f;
}  // namespace

Walkthrough atrium_walkthrough() {
  Walkthrough walkthrough;
  walkthrough.frame_count = 4900;
  walkthrough.frames_per_second = 30.0f;
  // (x, z) of each control point and where it looks. The arcades are crossed through the bays at
  // x = 10 and x = -14 (between columns, no drapes there); the creatures stand near z = 0, so the
  // hall is walked at z = 3.
  struct Key {
    vec2 at, look;
  };
  const Key keys[] = {
      {{-18.0f, 7.0f}, {-12.0f, 7.0f}},  // +z aisle, walking towards +x
      {{-10.0f, 7.0f}, {-4.0f, 7.0f}},
      {{-2.0f, 7.0f}, {4.0f, 7.0f}},
      {{5.0f, 7.0f}, {10.0f, 6.0f}},
      {{8.6f, 6.6f}, {10.0f, 2.0f}},     // turn into the hall between the columns at x = 8 and 12
      {{10.0f, 5.0f}, {6.0f, 1.5f}},
      {{9.0f, 3.2f}, {3.0f, 1.0f}},      // down the hall, looking at the creatures ahead
      {{5.0f, 3.0f}, {-1.0f, 0.5f}},
      {{0.0f, 3.0f}, {-6.0f, 0.5f}},
      {{-5.0f, 3.0f}, {-11.0f, 0.0f}},
      {{-10.0f, 3.0f}, {-14.5f, -3.0f}},
      {{-13.2f, 0.8f}, {-14.0f, -6.0f}}, // across the hall between the dinosaur and the armadillo
      {{-14.0f, -5.0f}, {-10.0f, -7.0f}},
      {{-11.5f, -7.0f}, {-5.0f, -7.0f}}, // -z aisle, walking towards +x
      {{-3.0f, -7.0f}, {3.0f, -7.0f}},
      {{6.0f, -7.0f}, {12.0f, -7.0f}},
      {{14.0f, -7.0f}, {20.0f, -6.0f}},
      {{18.0f, -6.5f}, {19.0f, -2.0f}},  // end: turning towards the hall's doorway
  };
  for (const Key& key : keys) {
    walkthrough.camera.points.emplace_back(key.at.x, kEye, key.at.y);
    walkthrough.camera.targets.emplace_back(key.look.x, kLookHeight, key.look.y);
  }
  walkthrough.camera.fov_y_degrees = 60.0f;
  // The light runs the length of the hall and back every 980 frames (five round trips).
  const float reach = atrium::kHalfLength - 3.0f;
  walkthrough.light.points = {vec3(-reach, kLightHeight, 0.0f), vec3(reach, kLightHeight, 0.0f)};
  walkthrough.light.period_frames = 980;
  return walkthrough;
}

PointLight atrium_light() {
  PointLight light;
  light.position = vec3(0.0f, kLightHeight, 0.0f);
  light.color = vec3(1.0f, 0.93f, 0.82f);  // warm, like the paper's torch-lit courtyard
  light.intensity = 24.0f;  // with the renderer's albedo / pi diffuse, exposure 1 keeps the floor below the light out of saturation
  light.range = 14.0f;                     // half strength 14 m away: reaches both ends of the hall
  return light;
}

}  // namespace glint::procedural
