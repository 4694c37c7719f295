#pragma once
// The `atrium` and `atrium-simple` built-in scenes: a procedural stand-in for the paper's test scene
// (Crytek Sponza with 4 armadillos and 2 T-Rex): the building (atrium_architecture.h), six
// polygonised creatures in the hall (creatures.h; the two dinosaurs deformable), procedural
// textures (textures.h), the light and the walkthrough (atrium_walkthrough.h). Sizes match the
// paper: `full` ~330k vertices and ~618k triangles (armadillos 35k, dinosaurs 20k vertices each);
// `simple` ~182k vertices (armadillos 3.5k, dinosaurs 7.5k).
#include "scene/scene.h"

#include <cstddef>

namespace glint::procedural {

enum class AtriumDetail { full, simple };

struct AtriumCounts {
  std::size_t armadillo_vertices;
  std::size_t dinosaur_vertices;
};
AtriumCounts atrium_creature_targets(AtriumDetail detail);

// Names of the creature meshes start with these.
inline constexpr const char* kArmadilloPrefix = "armadillo";
inline constexpr const char* kDinosaurPrefix = "dinosaur";

Scene make_atrium(AtriumDetail detail);

}  // namespace glint::procedural
