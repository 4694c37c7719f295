#pragma once
// glTF cameras -> glint's fixed camera. Internal to the scene module (it exposes tinygltf types).
// glint renders through one camera, so the first camera node the loader meets (depth first from the
// scene's root nodes, in file order) becomes a fixed camera (CameraPathSpec::fixed):
//   position      = the node's world transform applied to the origin
//   looks along   = the node's world -Z (a glTF camera looks down its local -Z)
//   fov_y_degrees = perspective.yfov (radians) in degrees, when it lies in 1..179 degrees
// Not kept: the camera's roll (glint's cameras keep world +Y up), aspectRatio (the image size comes
// from the command line), znear/zfar (glint fits its clip range to the scene); an orthographic
// camera keeps its place and direction and gets a perspective view (with a warning).
#include "core/math.h"
#include "scene/walkthrough.h"

#include <tiny_gltf.h>

#include <optional>
#include <string>

namespace glint {

struct GltfCameraNode {
  int node = -1;
  mat4 world{1.0f};  // the node's object-to-world transform
};

// The fixed camera of `camera_node` (whose `camera` index is >= 0), with the default fov unless the
// camera has a usable yfov. A camera index out of range is a glint::Error naming `label` (the file);
// a transform that gives no direction (a zero scale) is a warning and no camera.
std::optional<CameraPathSpec> gltf_fixed_camera(const tinygltf::Model& model, const GltfCameraNode& camera_node,
                                                const std::string& label);

}  // namespace glint
