#include "scene/gltf_cameras.h"

#include "core/error.h"
#include "core/log.h"

#include <algorithm>
#include <cmath>

namespace glint {

std::optional<CameraPathSpec> gltf_fixed_camera(const tinygltf::Model& model, const GltfCameraNode& camera_node,
                                                const std::string& label) {
  const tinygltf::Node& node = model.nodes.at(static_cast<std::size_t>(camera_node.node));
  const std::string where = fmt::format("{}: nodes[{}]", label, camera_node.node);
  if (node.camera < 0 || static_cast<std::size_t>(node.camera) >= model.cameras.size())
    fail("{}: camera {} does not exist ({} cameras)", where, node.camera, model.cameras.size());
  const tinygltf::Camera& camera = model.cameras[static_cast<std::size_t>(node.camera)];

  const vec3 position = vec3(camera_node.world * vec4(0.0f, 0.0f, 0.0f, 1.0f));
  const vec3 forward = vec3(camera_node.world * vec4(0.0f, 0.0f, -1.0f, 0.0f));
  const float length = glm::length(forward);
  if (!is_finite(position) || !(length > 0.0f) || !std::isfinite(length)) {
    log_warning("{}: the camera's transform gives no position or view direction; the default camera is used", where);
    return std::nullopt;
  }
  // The target one unit ahead, or further for large coordinates, so it stays apart from the position
  // in float.
  const float ahead = std::max({1.0f, std::abs(position.x), std::abs(position.y), std::abs(position.z)});
  CameraPathSpec spec = CameraPathSpec::fixed(position, position + ahead * (forward / length));

  if (camera.type == "perspective") {
    const double degrees = camera.perspective.yfov * 180.0 / 3.14159265358979323846;
    if (degrees >= 1.0 && degrees <= 179.0)
      spec.fov_y_degrees = static_cast<float>(degrees);
    else
      log_warning("{}: camera {}: yfov {} rad is outside 1..179 degrees; {} degrees are used", where, node.camera,
                  camera.perspective.yfov, spec.fov_y_degrees);
  } else {
    log_warning("{}: camera {} is {}; glint renders it in perspective ({} degrees)", where, node.camera,
                camera.type.empty() ? "of no type" : camera.type, spec.fov_y_degrees);
  }
  return spec;
}

}  // namespace glint
