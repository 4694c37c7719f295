#pragma once
// The atrium's creatures, stand-ins for the paper's armadillos and T-Rex dinosaurs: implicit shapes
// (smooth unions of ellipsoids and tapered capsules, scene/procedural/sdf.h) polygonised to a
// closed mesh with a requested vertex count. Object space: y up, feet on y = 0, facing +x (the
// dinosaur's body axis is x, which its sine deformer waves along).
#include "scene/procedural/sdf.h"
#include "scene/scene.h"

#include <cstddef>
#include <string>

namespace glint::procedural {

// Pose and proportion variations, so the four armadillos are not clones.
struct ArmadilloPose {
  float scale = 1.0f;       // overall size (1: about 1.8 m tall)
  float arm_raise = 0.0f;   // metres the hands are lifted
  float ear_length = 1.0f;  // relative ear size
  float tail_curl = 0.0f;   // sideways (z) offset of the tail tip, metres
  float head_tilt = 0.0f;   // metres the snout tip is raised
};

struct DinosaurPose {
  float scale = 1.0f;       // overall size (1: about 5.4 m long, 2.4 m tall)
  float jaw_open = 0.25f;   // radians
  float tail_sway = 0.0f;   // sideways (z) offset of the tail tip, metres
};

// Deterministic variations for creature number `index`.
ArmadilloPose armadillo_pose(int index);
DinosaurPose dinosaur_pose(int index);

BlendedShape armadillo_shape(const ArmadilloPose& pose);
BlendedShape dinosaur_shape(const DinosaurPose& pose);

// Polygonises `shape` to about `target_vertices` (within 1.5 %) with normals from the field
// gradient. `initial_cell` (optional) starts the resolution search from a similar shape's cell size,
// which usually saves the search's preliminary counts.
struct CreatureMesh {
  Mesh mesh;
  float cell_size = 0.0f;
};
CreatureMesh creature_mesh(const BlendedShape& shape, std::size_t target_vertices, const std::string& name,
                           float initial_cell = 0.0f);

// The dinosaurs' default deformation: a vertical wave travelling along the body, amplitude about
// 2 % of the body length.
SineDeform dinosaur_deform(const DinosaurPose& pose);

}  // namespace glint::procedural
