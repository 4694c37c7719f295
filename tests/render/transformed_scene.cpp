#include "transformed_scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdlib>

namespace glint::testing {

Scene transformed(Scene scene, float scale, vec3 offset) {
  const mat4 placement = glm::translate(mat4(1.0f), offset) * glm::scale(mat4(1.0f), vec3(scale));
  const auto place = [&](vec3& point) { point = point * scale + offset; };
  for (Instance& instance : scene.instances) instance.transform = placement * instance.transform;
  place(scene.light.position);
  scene.light.range *= scale;
  for (vec3& point : scene.walkthrough.camera.points) place(point);
  for (vec3& point : scene.walkthrough.camera.targets) place(point);
  for (vec3& point : scene.walkthrough.light.points) place(point);
  if (scene.reflection_fade) {
    scene.reflection_fade->start *= scale;
    scene.reflection_fade->end *= scale;
  }
  return scene;
}

FrameState moved(FrameState frame, vec3 offset) {
  frame.camera.position += offset;
  frame.camera.target += offset;
  frame.light_position += offset;
  return frame;
}

std::string ImageDifference::text() const {
  return std::to_string(pixels) + " pixels differ by more than " + std::to_string(threshold) + ", the most by " +
         std::to_string(largest);
}

ImageDifference image_difference(const ImageRgba8& a, const ImageRgba8& b, int threshold) {
  ImageDifference result;
  result.threshold = threshold;
  for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[i][c]) - int(b.pixels[i][c])));
    result.pixels += d > threshold;
    result.largest = std::max(result.largest, d);
  }
  return result;
}

}  // namespace glint::testing
