#pragma once
#include "scene/scene.h"

namespace glint {

// For scenes that come without a walkthrough (a bare OBJ or glTF): the camera circles inside the
// world bounds at a third of their height looking at the centre, and the light sits above the
// centre and sweeps along the longest horizontal axis. Call after the geometry is in place.
void assign_default_walkthrough(Scene& scene);

}  // namespace glint
