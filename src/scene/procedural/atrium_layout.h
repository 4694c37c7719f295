#pragma once
// The atrium's floor plan and elevations, shared by the geometry, the walkthrough and the tests
// (so a test can check the camera against the very columns that were built).
//
// Plan (metres, y up): a courtyard hall along x, open to the sky, between two arcades of round
// columns at z = +-kColumnLine; side aisles behind them up to back walls at z = +-kAisleWall; end
// walls with doorways at x = +-kHalfLength. Two storeys: ground arcades with large arches, an upper
// gallery (floor at kGalleryFloor) with twice as many smaller arches and a balustrade.
#include "core/math.h"

#include <vector>

namespace glint::procedural::atrium {

constexpr float kHalfLength = 20.0f;         // inner faces of the end walls
constexpr float kColumnLine = 5.0f;          // column centres, both storeys
constexpr float kAisleWall = 8.5f;           // inner faces of the back walls
constexpr float kOuterWallThickness = 0.5f;

constexpr float kBay = 4.0f;                 // ground storey column spacing
constexpr int kBays = 10;
constexpr float kLowerColumnRadius = 0.3f;
constexpr float kLowerAbacusHalf = 0.4f;     // half width of the capital block
constexpr float kLowerSpring = 3.4f;         // arches spring from the capitals here
constexpr float kLowerArchRadius = kBay / 2.0f - kLowerAbacusHalf;
constexpr float kArcadeHalfThickness = 0.3f;
constexpr float kAisleCeiling = 5.7f;
constexpr float kGalleryFloor = 6.0f;

constexpr float kUpperBay = 2.0f;            // upper storey: two arches per ground bay
constexpr int kUpperBays = 20;
constexpr float kUpperColumnRadius = 0.16f;
constexpr float kUpperAbacusHalf = 0.22f;
constexpr float kUpperSpring = 8.6f;
constexpr float kUpperArchRadius = kUpperBay / 2.0f - kUpperAbacusHalf;
constexpr float kUpperHalfThickness = 0.2f;
constexpr float kRoofLevel = 10.6f;          // gallery ceiling and top of the arcades
constexpr float kBalustradeTop = 7.02f;

// Column centres (x, z) of each storey.
std::vector<vec2> lower_column_centres();
std::vector<vec2> upper_column_centres();

// Centre x of ground bay `index` (0 .. kBays - 1, from -x to +x).
float bay_centre(int index);
// Drapes hang in the even bays; the camera crosses the arcades only through odd bays.
bool bay_has_drape(int index);

// The walkable inside: floor to gallery ceiling, wall to wall.
Aabb interior_bounds();

struct CreaturePlacement {
  enum class Kind { armadillo, dinosaur };
  Kind kind;
  int variant;         // index into armadillo_pose / dinosaur_pose
  vec2 position;       // (x, z) on the floor
  float yaw_degrees;   // rotation about +y; 0 faces +x
};
// Six creatures along the middle of the hall, spaced out, facing various ways (the paper's Fig. 4).
std::vector<CreaturePlacement> creature_placements();

}  // namespace glint::procedural::atrium
