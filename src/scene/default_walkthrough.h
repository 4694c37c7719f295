#pragma once
#include "scene/scene.h"
#include "scene/walkthrough.h"

#include <optional>

namespace glint {

// For scenes that come without a walkthrough (a bare OBJ or glTF, a scene file without "camera" or
// "light"): a camera loop in free space that sees the geometry, unless `camera` is given (a glTF
// camera, a scene file's camera), and a light in free space that lights what the camera sees (one
// that follows the camera, lifted above it, or a sweep or fixed point), chosen among candidates by
// casting rays against the scene's triangles (default_walkthrough.cpp says how; docs/scene-format.md).
// An interior gets a loop inside it at a third of its height, an object or a flat scene a loop around
// and above it. Call after the geometry is in place and walkthrough.frame_count is final (a light
// that follows the camera takes the whole walkthrough for its path); the fov is kept.
void assign_default_walkthrough(Scene& scene, const std::optional<CameraPathSpec>& camera = std::nullopt);

}  // namespace glint
