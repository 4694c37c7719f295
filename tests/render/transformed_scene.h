#pragma once
// Copies of a scene moved or scaled as a whole, and how far two renders of them differ: the tests
// that a scene renders the same picture at any scale (scene_reflection_fade_test.cpp) and far from
// the origin (far_from_origin_test.cpp).
#include "core/image.h"
#include "core/math.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <string>

namespace glint::testing {

// `scene` scaled by `scale` about the origin, then moved by `offset`: its instances, light and
// walkthrough (the light's range and the scene's own fade, if any, scale too).
Scene transformed(Scene scene, float scale, vec3 offset);

// `frame` (camera and light) moved by `offset`, as transformed(scene, 1, offset) moves its scene.
FrameState moved(FrameState frame, vec3 offset);

struct ImageDifference {
  int threshold = 8;  // a pixel differs when some rgb channel differs by more than this
  int pixels = 0;     // pixels that differ
  int largest = 0;    // the largest channel difference
  std::string text() const;
};

// How `a` and `b` (same size) differ, pixel by pixel, at `threshold` levels.
ImageDifference image_difference(const ImageRgba8& a, const ImageRgba8& b, int threshold = 8);

}  // namespace glint::testing
