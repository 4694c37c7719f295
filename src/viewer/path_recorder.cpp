#include "viewer/path_recorder.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

namespace glint::viewer {
namespace {

nlohmann::json to_json(const std::vector<vec3>& points) {
  nlohmann::json list = nlohmann::json::array();
  for (const vec3& p : points) list.push_back({p.x, p.y, p.z});
  return list;
}

}  // namespace

void PathRecorder::sample(const CameraState& camera) {
  if (!recording_) return;
  if (!points_.empty() && glm::distance(points_.back(), camera.position) < kMinStep) return;
  const vec3 direction = camera.target - camera.position;
  if (glm::length(direction) < 1e-6f) return;
  points_.push_back(camera.position);
  targets_.push_back(camera.position + glm::normalize(direction) * kTargetDistance);
}

void PathRecorder::save(const std::filesystem::path& scene_file, const std::filesystem::path& out) const {
  if (points_.size() < 2)
    fail("record: {} camera point{} recorded; fly with recording on to record a path of two or more", points_.size(),
         points_.size() == 1 ? "" : "s");
  if (!scene_file.string().ends_with(".scene.json"))
    fail("record: the scene {} is not a scene file (*.scene.json), so it has no camera path to replace",
         scene_file.string());
  std::ifstream in(scene_file, std::ios::binary);
  if (!in) fail("{}: cannot read the scene file", scene_file.string());
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json scene;
  try {
    scene = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
  } catch (const nlohmann::json::exception& error) {
    fail("{}: {}", scene_file.string(), error.what());
  }
  nlohmann::json& camera = scene["camera"];
  if (!camera.is_object()) camera = nlohmann::json::object();
  camera.erase("position");
  camera.erase("target");
  camera["path"] = to_json(points_);
  camera["targets"] = to_json(targets_);
  write_file_atomically(out, scene.dump(2) + "\n");
}

}  // namespace glint::viewer
