#pragma once
// The atrium's building (scene/procedural/atrium_layout.h): floor, two storeys of colonnades with
// round arches, aisles with ceilings and beams, brick back and end walls with doorways, a
// balustrade along the gallery and cloth banners. One mesh per part (one material each), all in
// world space with identity instances.
#include "scene/scene.h"

#include <cstdint>

namespace glint::procedural {

struct ArchitectureMaterials {
  std::uint32_t marble = 0, stone = 0, brick = 0, plaster = 0, wood = 0, fabric_red = 0, fabric_blue = 0;
  std::uint32_t polished_stone = 0;  // the gallery floor: stone, honed to a rough gloss
  std::uint32_t metal = 0;           // the balustrade: brushed bronze
};

// Tessellation knobs: walls, floors and ceilings are split into quads of at most `flat_segment`
// metres (the floor at `floor_segment`), small blocks (plinths, capitals, beams, rails, cornices)
// at `trim_segment`, round parts get `column_segments` around. The defaults give the paper's
// architecture size (~150k vertices, ~258k triangles).
struct ArchitectureDetail {
  float floor_segment = 0.16f;
  float flat_segment = 0.25f;
  float trim_segment = 1.0f;
  int column_segments = 24;
  int baluster_segments = 10;
  int drape_columns = 24;
  int drape_rows = 42;
};

// Appends the building's meshes and instances to `scene`.
void add_atrium_architecture(Scene& scene, const ArchitectureMaterials& materials, const ArchitectureDetail& detail);

}  // namespace glint::procedural
