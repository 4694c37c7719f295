#pragma once
// Walkthrough data: the camera's and the light's paths and the animation length. This is the data a
// scene carries; scene/camera_path.h turns it into positions per frame (see FrameState).
#include "core/math.h"

#include <vector>

namespace glint {

struct CameraPathSpec {
  // The camera passes through these points on a centripetal Catmull-Rom spline at constant speed.
  // Exactly one point (with exactly one target) is a fixed camera: it stays there for every frame.
  std::vector<vec3> points;
  // Look-at targets on a second spline, traversed in step with the camera (same arc-length
  // fraction). Empty: the camera looks along the path's tangent.
  std::vector<vec3> targets;
  float fov_y_degrees = 60.0f;

  // A camera that does not move: at `position`, looking at `target`.
  static CameraPathSpec fixed(vec3 position, vec3 target, float fov_y_degrees = 60.0f) {
    return {{position}, {target}, fov_y_degrees};
  }
  bool is_fixed() const { return points.size() == 1; }
};

struct LightPathSpec {
  // The light goes from the first point to the last along this polyline at constant speed and back
  // again, once every `period_frames` frames. One point: a fixed light.
  std::vector<vec3> points;
  int period_frames = 980;
};

struct Walkthrough {
  CameraPathSpec camera;
  LightPathSpec light;
  int frame_count = 4900;           // the paper's walkthrough length
  float frames_per_second = 30.0f;  // converts frame numbers to seconds for the deformers
};

}  // namespace glint
