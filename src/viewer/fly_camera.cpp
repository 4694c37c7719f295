#include "viewer/fly_camera.h"

#include <algorithm>
#include <cmath>

namespace glint::viewer {
namespace {

constexpr float kPitchLimit = 89.0f * 3.14159265f / 180.0f;
constexpr float kRadiansPerPixel = 0.003f;

}  // namespace

FlyCamera::FlyCamera(const CameraState& camera) : position_(camera.position) {
  vec3 direction = camera.target - camera.position;
  if (glm::length(direction) < 1e-6f) direction = vec3(0.0f, 0.0f, -1.0f);
  direction = glm::normalize(direction);
  yaw_ = std::atan2(direction.x, -direction.z);
  pitch_ = std::clamp(std::asin(std::clamp(direction.y, -1.0f, 1.0f)), -kPitchLimit, kPitchLimit);
}

vec3 FlyCamera::forward() const {
  return {std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_)};
}

CameraState FlyCamera::state(float fov_y_degrees) const {
  CameraState camera;
  camera.position = position_;
  camera.target = position_ + forward();
  camera.fov_y_degrees = fov_y_degrees;
  return camera;
}

void FlyCamera::move(vec3 direction, float seconds) {
  if (glm::length(direction) < 1e-6f) return;
  direction = glm::normalize(direction);
  // Forward and right stay horizontal, as in walking; up is world up.
  const vec3 ahead(std::sin(yaw_), 0.0f, -std::cos(yaw_));
  const vec3 right(std::cos(yaw_), 0.0f, std::sin(yaw_));
  position_ += (direction.x * right + direction.y * vec3(0.0f, 1.0f, 0.0f) + direction.z * ahead) * speed_ * seconds;
}

void FlyCamera::turn(float dx_pixels, float dy_pixels) {
  yaw_ += dx_pixels * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ - dy_pixels * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void FlyCamera::scroll(float notches) { speed_ = std::clamp(speed_ * std::pow(1.2f, notches), 0.05f, 500.0f); }

}  // namespace glint::viewer
