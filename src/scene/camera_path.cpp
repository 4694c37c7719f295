#include "scene/camera_path.h"

#include "core/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace glint {
namespace {

constexpr vec3 kWorldUp{0.0f, 1.0f, 0.0f};

// A view direction closer to `up` than this (|cos| above it) gets another up vector: lookAt's basis
// would be degenerate (NaN) at exactly parallel and unstable near it.
constexpr float kParallelCosine = 0.999f;

// The up vector to use for a camera looking along `forward` (unit): `preferred` unless it is
// (nearly) parallel, then -z, or +x when -z is parallel too, so a camera looking straight down or up
// keeps a fixed, predictable orientation.
vec3 stable_up(const vec3& forward, const vec3& preferred) {
  const float preferred_length = glm::length(preferred);
  if (preferred_length > 0.0f && std::isfinite(preferred_length) &&
      std::abs(glm::dot(forward, preferred / preferred_length)) < kParallelCosine)
    return preferred / preferred_length;
  const vec3 fallback{0.0f, 0.0f, -1.0f};
  if (std::abs(glm::dot(forward, fallback)) < kParallelCosine) return fallback;
  return vec3(1.0f, 0.0f, 0.0f);
}

// True when `target` is too close to `position` for a direction to be taken from their difference.
bool coincident(const vec3& position, const vec3& target) {
  const float scale = std::max({1.0f, std::abs(position.x), std::abs(position.y), std::abs(position.z)});
  return !(glm::length(target - position) > 1e-6f * scale);
}

bool all_equal(const std::vector<vec3>& points) {
  return std::all_of(points.begin(), points.end(), [&](const vec3& p) { return p == points.front(); });
}

// Checks the scalar fields first, so that their messages are not hidden behind a spline's.
const Walkthrough& validated(const Walkthrough& w) {
  if (w.frame_count <= 0) fail("walkthrough: frame_count must be > 0, got {}", w.frame_count);
  if (!(w.frames_per_second > 0.0f) || !std::isfinite(w.frames_per_second))
    fail("walkthrough: frames_per_second must be a finite number > 0, got {}", w.frames_per_second);
  if (w.light.period_frames <= 0) fail("walkthrough: light.period_frames must be > 0, got {}", w.light.period_frames);
  if (!(w.camera.fov_y_degrees > 0.0f && w.camera.fov_y_degrees < 180.0f))
    fail("walkthrough: camera.fov_y_degrees must be in (0, 180), got {}", w.camera.fov_y_degrees);
  if (w.camera.points.empty())
    fail("walkthrough: camera.points is empty: give at least 2 points for a path, or 1 point and 1 target for a "
         "fixed camera");
  if (w.camera.is_fixed()) {
    // One point: a camera that does not move. It has no path to look along, so it needs its target.
    const vec3 position = w.camera.points.front();
    if (!is_finite(position)) fail("walkthrough: camera.points: point 0 is not finite");
    if (w.camera.targets.size() != 1)
      fail("walkthrough: camera.points has 1 point, a fixed camera, which needs exactly 1 target in camera.targets "
           "(got {}); give at least 2 points for a path",
           w.camera.targets.size());
    if (!is_finite(w.camera.targets.front())) fail("walkthrough: camera.targets: point 0 is not finite");
    if (coincident(position, w.camera.targets.front()))
      fail("walkthrough: camera.targets: the fixed camera's target is its position ({}, {}, {}): it gives no "
           "direction to look in",
           position.x, position.y, position.z);
  }
  return w;
}

// Builds a spline, prefixing its error with the walkthrough field it came from.
CatmullRomSpline make_spline(const std::vector<vec3>& points, std::string_view field) {
  try {
    return CatmullRomSpline(points);
  } catch (const Error& e) {
    fail("walkthrough: {}: {}", field, e.what());
  }
}

LightPath make_light_path(const LightPathSpec& spec, vec3 rest_light_position) {
  try {
    return LightPath(spec.points, spec.period_frames, rest_light_position);
  } catch (const Error& e) {
    fail("walkthrough: light: {}", e.what());
  }
}

}  // namespace

mat4 CameraState::view() const {
  vec3 forward = coincident(position, target) ? vec3(0.0f, 0.0f, -1.0f) : glm::normalize(target - position);
  // The rotation from the direction alone: position + forward would round far from the origin
  // (by 0.004 at 1e5), turning the camera by a third of a pixel of a 160x90 frame; the translation
  // is then lookAt's own, -rotation x position (docs/render.md "precision far from the origin").
  mat4 view = glm::lookAt(vec3(0.0f), forward, stable_up(forward, up));
  view[3] = vec4(-(glm::mat3(view) * position), 1.0f);
  return view;
}

namespace {

// The camera spline, or none for a fixed camera.
std::optional<CatmullRomSpline> make_camera_path(const CameraPathSpec& camera) {
  if (camera.is_fixed()) return std::nullopt;
  return make_spline(camera.points, "camera.points");
}

}  // namespace

WalkthroughAnimation::WalkthroughAnimation(const Walkthrough& walkthrough, vec3 rest_light_position)
    : camera_path_(make_camera_path(validated(walkthrough).camera)),
      light_path_(make_light_path(walkthrough.light, rest_light_position)),
      frame_count_(walkthrough.frame_count),
      frames_per_second_(walkthrough.frames_per_second),
      fov_y_degrees_(walkthrough.camera.fov_y_degrees) {
  if (!camera_path_) fixed_position_ = walkthrough.camera.points.front();
  const std::vector<vec3>& targets = walkthrough.camera.targets;
  if (targets.empty()) return;
  for (std::size_t i = 0; i < targets.size(); ++i)
    if (!is_finite(targets[i])) fail("walkthrough: camera.targets: point {} is not finite", i);
  // One target (or several that coincide) is a fixed look-at point; a spline needs two distinct ones.
  if (all_equal(targets))
    fixed_target_ = targets.front();
  else
    target_path_.emplace(make_spline(targets, "camera.targets"));
}

WalkthroughAnimation::WalkthroughAnimation(const Scene& scene)
    : WalkthroughAnimation(scene.walkthrough, scene.light.position) {}

float WalkthroughAnimation::camera_speed_per_frame() const {
  if (!camera_path_ || frame_count_ <= 1) return 0.0f;
  return static_cast<float>(camera_path_->length_d() / double(frame_count_ - 1));
}

FrameState WalkthroughAnimation::at(int frame) const {
  if (frame < 0 || frame >= frame_count_)
    fail("walkthrough: frame {} is out of range [0, {})", frame, frame_count_);
  // Constant speed: equal frame steps are equal arc-length steps; the last frame is the path's end.
  const double fraction = frame_count_ > 1 ? double(frame) / double(frame_count_ - 1) : 0.0;

  FrameState state;
  state.frame = frame;
  state.time_seconds = static_cast<float>(double(frame) / double(frames_per_second_));
  state.light_position = light_path_.at(frame);
  CameraState& camera = state.camera;
  camera.fov_y_degrees = fov_y_degrees_;
  if (fixed_position_) {  // validated: one target, apart from the position
    camera.position = *fixed_position_;
    camera.target = *fixed_target_;
    camera.up = stable_up(glm::normalize(camera.target - camera.position), kWorldUp);
    return state;
  }
  const double s = fraction * camera_path_->length_d();
  camera.position = vec3(camera_path_->position_at_distance_d(s));
  // A point ahead along the path's tangent; one unit ahead, or further for huge coordinates so that
  // it stays distinguishable from the position in float.
  const vec3 p = camera.position;
  const float ahead = std::max({1.0f, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  const vec3 along_path = p + ahead * vec3(camera_path_->tangent_at_distance_d(s));
  if (target_path_)
    camera.target = vec3(target_path_->position_at_distance_d(fraction * target_path_->length_d()));
  else if (fixed_target_)
    camera.target = *fixed_target_;
  else
    camera.target = along_path;
  // A target on the camera gives no direction: look along the path instead.
  if (coincident(camera.position, camera.target)) camera.target = along_path;
  camera.up = stable_up(glm::normalize(camera.target - camera.position), kWorldUp);
  return state;
}

}  // namespace glint
