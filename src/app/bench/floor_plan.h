#pragma once
// Fig. 4 of the paper: the floor plan of the scene with the camera path, seen from above (y is up;
// x across, z down the page). What stands at walking height is rasterised into a coarse grid, the
// deforming meshes (the paper's armadillos and dinosaurs) marked apart, and the walkthrough's camera
// and light paths sampled, with the camera at the quality tables' frames (1800, 2100, 2300, 4400).
#include "scene/scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace glint::bench {

// The longer horizontal side of the bounds gets this many grid cells.
inline constexpr int kFloorPlanCells = 200;

// {"scene", "bounds": {"min", "max"}, "grid": {"origin": [x, z], "cell", "columns", "rows", "slab": [y0, y1],
//  "cells": one string per row, z ascending: '.' empty, '#' geometry within the slab, 'd' a deformable
//  mesh}, "camera": [[x, z], ...], "light": [[x, z], ...] (every `path_step` frames and the last),
//  "path_step", "marked_frames": [{"frame", "camera": [x, z], "target": [x, z]}]}.
// The slab is walking height: from a tenth of the camera's lowest height above the floor (the
// scene's lowest point) to one and a half times its highest, so floors and high ceilings are left out.
// glint::Error for an invalid walkthrough (WalkthroughAnimation's).
nlohmann::json floor_plan_json(const Scene& scene, const std::string& scene_name);

}  // namespace glint::bench
