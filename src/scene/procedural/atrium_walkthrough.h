#pragma once
// The atrium's walkthrough (the paper's Fig. 4): 4900 frames at 30 fps along an S through the
// three halls (along one aisle, back down the central hall past the creatures, along the other
// aisle), and a point light sweeping up and down the hall at a fixed height.
#include "scene/scene.h"

namespace glint::procedural {

Walkthrough atrium_walkthrough();
PointLight atrium_light();

}  // namespace glint::procedural
