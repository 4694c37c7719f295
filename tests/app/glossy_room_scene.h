#pragma once
// A scene file small enough for CLI tests of glossy reflections on llvmpipe: a glossy reflective
// floor (roughness 0.3), a cube on it that deforms (a sine wave), a camera moving sideways and a light
// sweeping over it, 1900 frames (so the quality frame 1800 exists).
#include "support/temp_folder.h"

#include <filesystem>

namespace glint::testing {

inline std::filesystem::path write_glossy_room(const TempFolder& folder) {
  folder.write("floor.obj", "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nf 1 4 3 2\n");
  folder.write("cube.obj",
               "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\n"
               "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
               "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n");
  return folder.write("room.scene.json", R"({
  "frames": 1900,
  "meshes": [
    {"file": "floor.obj", "material": {"diffuse": [0.4, 0.4, 0.45], "reflectivity": 0.6, "roughness": 0.3}},
    {"file": "cube.obj", "material": {"diffuse": [0.8, 0.3, 0.2], "reflectivity": 0.2, "roughness": 0.1},
     "deform": {"type": "sine", "axis": "y", "along": "x", "amplitude": 0.2, "frequency": 3, "speed": 4}}
  ],
  "light": {"intensity": 12, "range": 20, "path": [[-3, 3, 1], [3, 3, 1]], "period_frames": 60},
  "camera": {"path": [[-1, 1.2, 4], [1, 1.2, 4]], "targets": [[0, 0.4, 0], [0, 0.4, 0]]}
})");
}

}  // namespace glint::testing
