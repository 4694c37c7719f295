#include "scene/procedural/atrium_layout.h"

namespace glint::procedural::atrium {

std::vector<vec2> lower_column_centres() {
  std::vector<vec2> centres;
  for (const float side : {-1.0f, 1.0f})
    for (int i = 1; i < kBays; ++i) centres.emplace_back(-kHalfLength + kBay * static_cast<float>(i), side * kColumnLine);
  return centres;
}

std::vector<vec2> upper_column_centres() {
  std::vector<vec2> centres;
  for (const float side : {-1.0f, 1.0f})
    for (int i = 1; i < kUpperBays; ++i)
      centres.emplace_back(-kHalfLength + kUpperBay * static_cast<float>(i), side * kColumnLine);
  return centres;
}

float bay_centre(int index) { return -kHalfLength + kBay * (static_cast<float>(index) + 0.5f); }

bool bay_has_drape(int index) { return index % 2 == 0; }

Aabb interior_bounds() {
  Aabb box;
  box.extend(vec3(-kHalfLength, 0.0f, -kAisleWall));
  box.extend(vec3(kHalfLength, kRoofLevel, kAisleWall));
  return box;
}

std::vector<CreaturePlacement> creature_placements() {
  using Kind = CreaturePlacement::Kind;
  return {
      {Kind::armadillo, 0, {-15.5f, 0.3f}, 60.0f},
      {Kind::dinosaur, 0, {-9.0f, -0.3f}, 165.0f},
      {Kind::armadillo, 1, {-3.5f, 0.4f}, -110.0f},
      {Kind::armadillo, 2, {2.0f, -0.4f}, 25.0f},
      {Kind::dinosaur, 1, {8.5f, 0.3f}, -15.0f},
      {Kind::armadillo, 3, {15.0f, -0.2f}, 200.0f},
  };
}

}  // namespace glint::procedural::atrium
