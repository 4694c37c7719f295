#include "rt/tiny_scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace glint::testing {
namespace {

Mesh quad(const std::string& name, vec3 a, vec3 b, vec3 c, vec3 d, uint32_t material) {
  Mesh mesh;
  mesh.name = name;
  mesh.positions = {a, b, c, d};
  const vec3 n = glm::normalize(glm::cross(b - a, c - a));
  mesh.normals.assign(4, n);
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  return mesh;
}

Mesh sheet(int cells) {
  Mesh mesh;
  mesh.name = "sheet";
  for (int y = 0; y <= cells; ++y)
    for (int x = 0; x <= cells; ++x) {
      mesh.positions.push_back(vec3(static_cast<float>(x) / static_cast<float>(cells),
                                    static_cast<float>(y) / static_cast<float>(cells), 0.0f));
      mesh.normals.push_back(vec3(0, 0, 1));
    }
  const auto at = [&](int x, int y) { return static_cast<uint32_t>(y * (cells + 1) + x); };
  for (int y = 0; y < cells; ++y)
    for (int x = 0; x < cells; ++x) {
      mesh.indices.insert(mesh.indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      mesh.indices.insert(mesh.indices.end(), {at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  mesh.material = 1;
  mesh.deformable = true;
  SineDeform wave;
  wave.displace_axis = 2;
  wave.wave_axis = 0;
  wave.amplitude = 0.2f;
  wave.frequency = 6.0f;
  wave.speed = 3.0f;
  mesh.deform = wave;
  return mesh;
}

}  // namespace

Scene make_tiny_scene(int sheet_cells) {
  Scene scene;
  scene.name = "tiny";
  scene.source = "built-in test scene";
  Material mirror;
  mirror.name = "mirror floor";
  mirror.reflectivity = 0.5f;
  Material matte;
  matte.name = "matte";
  scene.materials = {mirror, matte};
  // Counter-clockwise seen from above (+y) and from the front (+z).
  scene.meshes.push_back(quad("floor", vec3(-10, 0, 10), vec3(10, 0, 10), vec3(10, 0, -10), vec3(-10, 0, -10), 0));
  scene.meshes.push_back(quad("wall", vec3(-10, 0, -5), vec3(10, 0, -5), vec3(10, 8, -5), vec3(-10, 8, -5), 1));
  scene.meshes.push_back(sheet(sheet_cells));
  scene.instances.push_back({"floor", 0, mat4(1.0f)});
  scene.instances.push_back({"wall", 1, mat4(1.0f)});
  scene.instances.push_back({"sheet a", 2, glm::translate(mat4(1.0f), vec3(-2, 1, 0))});
  scene.instances.push_back(
      {"sheet b", 2, glm::rotate(glm::translate(mat4(1.0f), vec3(3, 1, 1)), glm::radians(90.0f), vec3(0, 1, 0))});
  scene.walkthrough.camera.points = {vec3(0, 2, 8), vec3(1, 2, 6), vec3(2, 2.5f, 4)};
  scene.walkthrough.camera.targets = {vec3(0, 0.5f, -5)};
  scene.walkthrough.camera.fov_y_degrees = 60.0f;
  scene.walkthrough.light.points = {vec3(0, 6, 0)};
  scene.walkthrough.frame_count = 100;
  scene.validate();
  return scene;
}

}  // namespace glint::testing
