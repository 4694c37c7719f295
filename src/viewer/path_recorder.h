#pragma once
// Records the flown camera as a walkthrough camera path: a sample (position and a look-at point
// kTargetDistance ahead) whenever the camera moved at least kMinStep since the last one, and
// writes them into a copy of a scene file (*.scene.json) as its "camera" "path" and "targets", so
// `glint render` and `glint view` of that file follow the flight.
#include "core/math.h"
#include "scene/camera_path.h"

#include <filesystem>
#include <vector>

namespace glint::viewer {

class PathRecorder {
public:
  static constexpr float kMinStep = 0.25f;       // metres between samples
  static constexpr float kTargetDistance = 2.0f;  // metres from a sample to its look-at point

  void start() { recording_ = true; }
  void stop() { recording_ = false; }
  bool recording() const { return recording_; }
  void clear() { points_.clear(), targets_.clear(); }
  // Keeps `camera` when recording and it moved far enough from the last sample.
  void sample(const CameraState& camera);
  std::size_t size() const { return points_.size(); }

  // Writes `scene_file` (a *.scene.json file) to `out` with its camera path replaced by the samples
  // (its field of view kept). glint::Error for fewer than two samples, a scene that is not such a
  // file, or a file that cannot be read, parsed or written.
  void save(const std::filesystem::path& scene_file, const std::filesystem::path& out) const;

private:
  bool recording_ = false;
  std::vector<vec3> points_;
  std::vector<vec3> targets_;
};

}  // namespace glint::viewer
