#include "raster_test_scene.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace glint::testing {

Scene make_empty_test_scene(vec3 light) {
  Scene scene;
  scene.name = "raster-test";
  scene.source = "raster test";
  scene.light.position = light;
  scene.light.range = 10.0f;
  scene.light.intensity = 20.0f;
  scene.light.color = vec3(1.0f, 0.9f, 0.8f);
  scene.sky_color = vec3(0.5f, 0.6f, 0.7f);
  scene.walkthrough.camera.points = {vec3(0.0f, 1.0f, 5.0f), vec3(1.0f, 1.0f, 5.0f)};
  scene.walkthrough.frame_count = 10;
  return scene;
}

std::uint32_t add_material(Scene& scene, vec3 diffuse, float reflectivity, int texture) {
  Material material;
  material.name = "material" + std::to_string(scene.materials.size());
  material.diffuse = diffuse;
  material.reflectivity = reflectivity;
  material.roughness = 0.25f;
  material.diffuse_texture = texture;
  material.specular = vec3(0.3f);
  material.specular_exponent = 20.0f;
  scene.materials.push_back(material);
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

std::uint32_t add_quad(Scene& scene, vec3 origin, vec3 edge_u, vec3 edge_v, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "quad" + std::to_string(scene.meshes.size());
  mesh.positions = {origin, origin + edge_u, origin + edge_u + edge_v, origin + edge_v};
  mesh.normals.assign(4, glm::normalize(glm::cross(edge_u, edge_v)));
  mesh.uvs = {vec2(0.0f, 0.0f), vec2(1.0f, 0.0f), vec2(1.0f, 1.0f), vec2(0.0f, 1.0f)};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  mesh.material = material;
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.name = mesh.name;
  instance.mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
  return instance.mesh;
}

FrameState look_at(vec3 eye, vec3 target, vec3 light) {
  FrameState frame;
  frame.camera.position = eye;
  frame.camera.target = target;
  frame.camera.fov_y_degrees = 60.0f;
  frame.light_position = light;
  return frame;
}

vec3 pixel_ray(const render::FrameConstants& constants, int x, int y) {
  const float width = static_cast<float>(constants.viewport.x), height = static_cast<float>(constants.viewport.y);
  const vec2 ndc((static_cast<float>(x) + 0.5f) / width * 2.0f - 1.0f,
                 1.0f - (static_cast<float>(y) + 0.5f) / height * 2.0f);
  const mat4 inverse = glm::inverse(constants.view_projection);
  const vec4 near_point = inverse * vec4(ndc, -1.0f, 1.0f);
  const vec4 far_point = inverse * vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(vec3(far_point) / far_point.w - vec3(near_point) / near_point.w);
}

std::optional<vec3> hit_quad(vec3 origin, vec3 direction, vec3 quad_origin, vec3 edge_u, vec3 edge_v) {
  const vec3 normal = glm::cross(edge_u, edge_v);
  const float denominator = glm::dot(normal, direction);
  if (std::abs(denominator) < 1e-12f) return std::nullopt;
  const float t = glm::dot(normal, quad_origin - origin) / denominator;
  if (t <= 0.0f) return std::nullopt;
  const vec3 p = origin + t * direction;
  // Coordinates of p in the (edge_u, edge_v) frame.
  const vec3 d = p - quad_origin;
  const float uu = glm::dot(edge_u, edge_u), uv = glm::dot(edge_u, edge_v), vv = glm::dot(edge_v, edge_v);
  const float du = glm::dot(d, edge_u), dv = glm::dot(d, edge_v);
  const float det = uu * vv - uv * uv;
  const float s = (du * vv - dv * uv) / det, r = (dv * uu - du * uv) / det;
  if (s < 0.0f || s > 1.0f || r < 0.0f || r > 1.0f) return std::nullopt;
  return p;
}

Scene make_floor_with_occluders(std::vector<QuadGeometry>& occluders) {
  Scene scene = make_empty_test_scene(vec3(0.0f, 4.0f, 0.0f));
  const std::uint32_t floor = add_material(scene, vec3(0.7f, 0.6f, 0.5f), 0.3f);
  const std::uint32_t lid = add_material(scene, vec3(0.2f, 0.4f, 0.9f));
  scene.materials[lid].emissive = vec3(0.2f, 0.1f, 0.0f);
  const std::uint32_t wall = add_material(scene, vec3(0.9f, 0.9f, 0.2f));
  add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor);
  occluders = {{vec3(-1.0f, 2.0f, 1.0f), vec3(2.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -2.0f)},
               {vec3(3.0f, 0.0f, -1.5f), vec3(0.0f, 0.0f, 3.0f), vec3(0.0f, 1.0f, 0.0f)}};
  add_quad(scene, occluders[0].origin, occluders[0].edge_u, occluders[0].edge_v, lid);
  add_quad(scene, occluders[1].origin, occluders[1].edge_u, occluders[1].edge_v, wall);
  return scene;
}

bool light_blocked(vec3 point, vec3 light, const std::vector<QuadGeometry>& quads) {
  const float distance = glm::length(light - point);
  const vec3 direction = (light - point) / distance;
  for (const QuadGeometry& quad : quads) {
    const auto hit = hit_quad(point, direction, quad.origin, quad.edge_u, quad.edge_v);
    if (hit && glm::length(*hit - point) < distance) return true;
  }
  return false;
}

Scene mirror_floor_with_wall(float wall_z, vec2 wall_size) {
  Scene scene = make_empty_test_scene(vec3(0.0f, 6.0f, 0.0f));
  const std::uint32_t floor = add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t wall = add_material(scene, vec3(0.0f));
  scene.materials[wall].emissive = vec3(4.0f, 0.0f, 0.0f);
  add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor);
  // Edges x then y: the normal cross(x, y) = +z faces a camera at larger z.
  add_quad(scene, vec3(-0.5f * wall_size.x, 0.0f, wall_z), vec3(wall_size.x, 0.0f, 0.0f), vec3(0.0f, wall_size.y, 0.0f),
           wall);
  return scene;
}

FrameState camera_looking_down_the_floor() {
  return look_at(vec3(0.0f, 1.5f, 6.0f), vec3(0.0f, 0.8f, -4.0f), vec3(0.0f, 6.0f, 0.0f));
}

Scene mirror_strip_before_wall() {
  Scene scene = make_empty_test_scene(vec3(0.0f, 3.0f, 2.0f));
  const std::uint32_t floor = add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t wall = add_material(scene, vec3(0.8f, 0.6f, 0.3f));
  add_quad(scene, vec3(-0.5f, 0.0f, 4.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -6.0f), floor);
  add_quad(scene, vec3(-50.0f, -1.0f, -4.0f), vec3(100.0f, 0.0f, 0.0f), vec3(0.0f, 50.0f, 0.0f), wall);
  return scene;
}

Scene mirror_floor_under_ceiling() {
  Scene scene = make_empty_test_scene(vec3(0.0f, 3.0f, 0.0f));
  const std::uint32_t floor = add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t ceiling = add_material(scene, vec3(0.0f));
  scene.materials[ceiling].emissive = vec3(4.0f, 0.0f, 0.0f);
  add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor);
  // Edges -z then x: the normal cross(-z, x) = -y faces the floor.
  add_quad(scene, vec3(-6.0f, 4.0f, 8.0f), vec3(0.0f, 0.0f, -6.0f), vec3(12.0f, 0.0f, 0.0f), ceiling);
  return scene;
}

FrameState camera_looking_steeply_down() {
  const vec3 eye(0.0f, 1.5f, 6.0f);
  return look_at(eye, eye + vec3(0.0f, -std::sin(glm::radians(60.0f)), -std::cos(glm::radians(60.0f))),
                 vec3(0.0f, 3.0f, 0.0f));
}

}  // namespace glint::testing
