#pragma once
// Turns a Walkthrough (data) into per-frame states: where the camera is and looks, where the light
// is, and the frame's time. The camera moves at constant speed along a centripetal Catmull-Rom
// spline (so per-frame costs in the benchmarks are not skewed by the camera slowing down), the light
// ping-pongs along a polyline.
#include "core/math.h"
#include "scene/light_path.h"
#include "scene/scene.h"
#include "scene/spline.h"
#include "scene/walkthrough.h"

#include <optional>

namespace glint {

struct CameraState {
  vec3 position{0.0f};
  vec3 target{0.0f, 0.0f, -1.0f};
  vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 60.0f;

  // Right-handed look-at matrix (world to camera). Robust to a target equal to the position (looks
  // down -z) and to a view direction parallel to `up` (another up is chosen), so it is always finite.
  mat4 view() const;
};

struct FrameState {
  int frame = 0;
  float time_seconds = 0.0f;
  CameraState camera;
  vec3 light_position{0.0f};
};

class WalkthroughAnimation {
public:
  // Validates the walkthrough (frame_count > 0, frames_per_second > 0, light period_frames > 0, at
  // least 2 distinct camera points or a fixed camera (one point, one target apart from it), finite
  // points, 0 < fov < 180) and throws glint::Error naming the field otherwise. `rest_light_position` is where the light stays when the light path is empty
  // (pass the scene's PointLight::position).
  WalkthroughAnimation(const Walkthrough& walkthrough, vec3 rest_light_position);
  // The scene's walkthrough, with its light's position as the rest position.
  explicit WalkthroughAnimation(const Scene& scene);

  // The state of frame `frame`; throws glint::Error outside [0, frame_count()).
  FrameState at(int frame) const;

  int frame_count() const { return frame_count_; }
  // 0 for a fixed camera.
  float camera_path_length() const { return camera_path_ ? camera_path_->length() : 0.0f; }
  // One way, first light point to last (a full period covers twice this).
  float light_path_length() const { return light_path_.length(); }
  // Distance the camera covers between consecutive frames (0 for a one-frame walkthrough).
  float camera_speed_per_frame() const;

private:
  std::optional<CatmullRomSpline> camera_path_;  // empty: a fixed camera at fixed_position_
  std::optional<vec3> fixed_position_;
  std::optional<CatmullRomSpline> target_path_;  // two or more targets
  std::optional<vec3> fixed_target_;             // exactly one target
  LightPath light_path_;
  int frame_count_ = 0;
  float frames_per_second_ = 30.0f;
  float fov_y_degrees_ = 60.0f;
};

}  // namespace glint
