#pragma once
// The free-flight camera of `glint view`: a position, a heading (yaw about +y) and a pitch, moved
// in its own frame (WASD: forward and sideways, Q/E: down and up) at a speed the mouse wheel scales,
// and turned by mouse motion. It starts where the walkthrough's camera is and converts back to the
// renderer's CameraState (a look-at one metre ahead), so flying and following the path share one
// camera model.
#include "core/math.h"
#include "scene/camera_path.h"

namespace glint::viewer {

class FlyCamera {
public:
  FlyCamera() = default;
  // Where `camera` is, looking where it looks (its up vector is taken as +y).
  explicit FlyCamera(const CameraState& camera);

  // `fov_y_degrees` is kept from the walkthrough.
  CameraState state(float fov_y_degrees) const;
  vec3 position() const { return position_; }
  vec3 forward() const;  // unit view direction
  float speed() const { return speed_; }  // metres per second

  // Moves by `direction` (x: right, y: up, z: forward; any length, normalised here) for `seconds`.
  void move(vec3 direction, float seconds);
  // Turns by mouse motion in pixels (right and down positive).
  void turn(float dx_pixels, float dy_pixels);
  // Scales the speed by 1.2 per wheel notch (up: faster), kept in 0.05 .. 500 m/s.
  void scroll(float notches);

private:
  vec3 position_{0.0f};
  float yaw_ = 0.0f;    // radians; 0 looks down -z, positive turns towards +x
  float pitch_ = 0.0f;  // radians, kept within +-89 degrees
  float speed_ = 3.0f;
};

}  // namespace glint::viewer
