#include "scene/procedural/atrium.h"

#include "core/error.h"
#include "scene/camera_path.h"
#include "scene/mesh_checks.h"
#include "scene/mesh_ops.h"
#include "scene/presets.h"
#include "scene/procedural/atrium_layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace glint::procedural {
namespace {

// Each preset is generated once for the whole suite (about a second each).
const Scene& full_atrium() {
  static const Scene scene = make_atrium(AtriumDetail::full);
  return scene;
}
const Scene& simple_atrium() {
  static const Scene scene = make_atrium(AtriumDetail::simple);
  return scene;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }
bool is_creature(const Mesh& mesh) { return starts_with(mesh.name, kArmadilloPrefix) || starts_with(mesh.name, kDinosaurPrefix); }

void expect_within(double value, double expected, double relative, const std::string& what) {
  EXPECT_NEAR(value, expected, relative * expected) << what;
}

TEST(Atrium, FullPresetHasThePapersCounts) {
  const Scene& scene = full_atrium();
  expect_within(static_cast<double>(scene.vertex_count()), 330000, 0.05, "total vertices");
  expect_within(static_cast<double>(scene.triangle_count()), 618000, 0.05, "total triangles");
  int armadillos = 0, dinosaurs = 0;
  for (const Mesh& mesh : scene.meshes) {
    if (starts_with(mesh.name, kArmadilloPrefix)) {
      ++armadillos;
      expect_within(static_cast<double>(mesh.vertex_count()), 35000, 0.05, mesh.name);
    } else if (starts_with(mesh.name, kDinosaurPrefix)) {
      ++dinosaurs;
      expect_within(static_cast<double>(mesh.vertex_count()), 20000, 0.05, mesh.name);
    }
  }
  EXPECT_EQ(armadillos, 4);
  EXPECT_EQ(dinosaurs, 2);
}

TEST(Atrium, SimplePresetHasThePapersCounts) {
  const Scene& scene = simple_atrium();
  expect_within(static_cast<double>(scene.vertex_count()), 182000, 0.05, "total vertices");
  for (const Mesh& mesh : scene.meshes) {
    if (starts_with(mesh.name, kArmadilloPrefix)) expect_within(static_cast<double>(mesh.vertex_count()), 3500, 0.05, mesh.name);
    if (starts_with(mesh.name, kDinosaurPrefix)) expect_within(static_cast<double>(mesh.vertex_count()), 7500, 0.05, mesh.name);
  }
  // Same architecture in both presets.
  EXPECT_EQ(scene.meshes.size(), full_atrium().meshes.size());
  EXPECT_EQ(scene.meshes[0].positions, full_atrium().meshes[0].positions);
}

TEST(Atrium, SixCreatureInstancesAndTwoDeformableDinosaurs) {
  for (const Scene* scene : {&full_atrium(), &simple_atrium()}) {
    int creature_instances = 0;
    for (const Instance& instance : scene->instances) creature_instances += is_creature(scene->meshes[instance.mesh]) ? 1 : 0;
    EXPECT_EQ(creature_instances, 6);
    const std::vector<std::uint32_t> deformable = scene->deformable_meshes();
    ASSERT_EQ(deformable.size(), 2u);
    for (const std::uint32_t m : deformable) {
      const Mesh& mesh = scene->meshes[m];
      EXPECT_TRUE(starts_with(mesh.name, kDinosaurPrefix)) << mesh.name;
      ASSERT_TRUE(mesh.deform.has_value());
      // Visible but plausible: a few per cent of the ~5 m body.
      EXPECT_GT(mesh.deform->amplitude, 0.02f);
      EXPECT_LT(mesh.deform->amplitude, 0.05f * mesh.bounds().extent().x);
      EXPECT_EQ(mesh.deform->wave_axis, 0);  // along the body
      EXPECT_EQ(mesh.deform->displace_axis, 1);
    }
  }
}

TEST(Atrium, EveryMeshIsWellFormed) {
  const Scene& scene = full_atrium();
  EXPECT_EQ(scene.name, "atrium");
  EXPECT_EQ(scene.source, "built-in");
  EXPECT_NO_THROW(scene.validate());
  for (const Mesh& mesh : scene.meshes) {
    SCOPED_TRACE(mesh.name);
    ASSERT_GT(mesh.triangle_count(), 0u);
    ASSERT_EQ(mesh.normals.size(), mesh.vertex_count());
    if (!is_creature(mesh)) {
      ASSERT_EQ(mesh.uvs.size(), mesh.vertex_count());
    }
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      ASSERT_TRUE(is_finite(mesh.positions[v]));
      ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-3f);
    }
    std::size_t degenerate = 0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
      ASSERT_LT(std::max({mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]}), mesh.vertex_count());
      degenerate += is_degenerate_triangle(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                                           mesh.positions[mesh.indices[t + 2]]) ? 1 : 0;
    }
    EXPECT_EQ(degenerate, 0u);
    ASSERT_LT(mesh.material, scene.materials.size());
  }
  EXPECT_GE(scene.textures.size(), 6u);
  for (const Texture& texture : scene.textures) {
    EXPECT_EQ(texture.width, 512);
    EXPECT_EQ(texture.height, 512);
    EXPECT_EQ(texture.rgba.size(), 512u * 512u * 4u);
    EXPECT_FALSE(texture.placeholder);
  }
}

TEST(Atrium, FloorIsTheOnlyStronglyReflectiveSurface) {
  const Scene& scene = full_atrium();
  const Mesh& floor = scene.meshes[0];
  ASSERT_EQ(floor.name, "floor");
  const Material& marble = scene.materials[floor.material];
  EXPECT_GT(marble.reflectivity, 0.3f);
  EXPECT_GE(marble.diffuse_texture, 0);
  for (const Mesh& mesh : scene.meshes)
    if (&mesh != &floor) {
      EXPECT_LT(scene.materials[mesh.material].reflectivity, marble.reflectivity) << mesh.name;
    }
  // The floor faces up and lies at y = 0.
  EXPECT_EQ(floor.bounds().min.y, 0.0f);
  EXPECT_EQ(floor.bounds().max.y, 0.0f);
  EXPECT_EQ(floor.normals[0], vec3(0, 1, 0));
}

TEST(Atrium, WindingAgreesWithNormalsAndCreaturesAreClosedAndOutward) {
  const Scene& scene = full_atrium();
  for (const Mesh& mesh : scene.meshes) {
    SCOPED_TRACE(mesh.name);
    EXPECT_GE(testing::fraction_winding_matches_normals(mesh), is_creature(mesh) ? 0.995 : 0.999);
    if (!is_creature(mesh)) continue;
    const testing::EdgeReport edges = testing::edge_report(mesh);
    EXPECT_EQ(edges.not_shared_by_two, 0u);
    EXPECT_EQ(edges.inconsistent, 0u);
    EXPECT_GT(testing::signed_volume(mesh), 0.0);
  }
}

TEST(Atrium, GenerationIsDeterministic) {
  const Scene again = make_atrium(AtriumDetail::simple);
  const Scene& first = simple_atrium();
  ASSERT_EQ(again.meshes.size(), first.meshes.size());
  for (std::size_t m = 0; m < first.meshes.size(); ++m) {
    EXPECT_EQ(again.meshes[m].positions, first.meshes[m].positions) << first.meshes[m].name;
    EXPECT_EQ(again.meshes[m].normals, first.meshes[m].normals) << first.meshes[m].name;
    EXPECT_EQ(again.meshes[m].indices, first.meshes[m].indices) << first.meshes[m].name;
  }
  for (std::size_t t = 0; t < first.textures.size(); ++t) EXPECT_EQ(again.textures[t].rgba, first.textures[t].rgba);
}

// Creature footprints on the floor, in world space.
std::vector<Aabb> creature_boxes(const Scene& scene) {
  std::vector<Aabb> boxes;
  for (const Instance& instance : scene.instances)
    if (is_creature(scene.meshes[instance.mesh])) boxes.push_back(transform_aabb(instance.transform, scene.meshes[instance.mesh].bounds()));
  return boxes;
}

float distance_xz(const vec3& p, const Aabb& box) {
  const float dx = std::max({box.min.x - p.x, 0.0f, p.x - box.max.x});
  const float dz = std::max({box.min.z - p.z, 0.0f, p.z - box.max.z});
  return std::sqrt(dx * dx + dz * dz);
}

TEST(Atrium, CameraPathStaysInsideAndClearOfColumnsAndCreatures) {
  const Scene& scene = full_atrium();
  const CameraPathSpec& camera = scene.walkthrough.camera;
  ASSERT_GE(camera.points.size(), 8u);
  ASSERT_EQ(camera.targets.size(), camera.points.size());
  Aabb inside = atrium::interior_bounds();
  inside.min += vec3(0.5f);
  inside.max -= vec3(0.5f);
  for (const vec3& p : camera.points) {
    EXPECT_TRUE(inside.contains(p)) << p.x << " " << p.y << " " << p.z;
    EXPECT_NEAR(p.y, 1.7f, 0.2f);
  }
  for (const vec3& t : camera.targets) EXPECT_TRUE(atrium::interior_bounds().contains(t)) << t.x << " " << t.z;
  // Every frame's camera position, as the renderer will place it.
  const WalkthroughAnimation animation(scene);
  const std::vector<Aabb> creatures = creature_boxes(scene);
  ASSERT_EQ(creatures.size(), 6u);
  for (int f = 0; f < animation.frame_count(); ++f) {
    const vec3 p = animation.at(f).camera.position;
    ASSERT_TRUE(inside.contains(p)) << p.x << " " << p.z;
    for (const vec2 c : atrium::lower_column_centres())
      ASSERT_GT(glm::distance(vec2(p.x, p.z), c), atrium::kLowerAbacusHalf + 0.3f) << "near column at " << c.x << " " << c.y;
    for (const Aabb& box : creatures) ASSERT_GT(distance_xz(p, box), 0.5f) << "near creature at " << box.center().x;
    // Through the ground arcades only where no drape hangs.
    if (std::abs(std::abs(p.z) - atrium::kColumnLine) < 0.5f) {
      const int bay = static_cast<int>(std::floor((p.x + atrium::kHalfLength) / atrium::kBay));
      EXPECT_FALSE(atrium::bay_has_drape(bay)) << "through a drape at x = " << p.x;
    }
  }
}

TEST(Atrium, QualityFramesLookDownTheHallAtTheCreatures) {
  const Scene& scene = full_atrium();
  const Walkthrough& walk = scene.walkthrough;
  EXPECT_EQ(walk.frame_count, 4900);
  EXPECT_FLOAT_EQ(walk.frames_per_second, 30.0f);
  const WalkthroughAnimation animation(scene);
  std::vector<vec3> creatures;
  for (const Aabb& box : creature_boxes(scene)) creatures.push_back(box.center());
  auto frame = [&](int f, vec3& eye, vec3& direction) {
    const CameraState camera = animation.at(f).camera;
    eye = camera.position;
    direction = glm::normalize(camera.target - eye);
  };
  for (const int f : {1800, 2100, 2300}) {
    SCOPED_TRACE(f);
    vec3 eye, direction;
    frame(f, eye, direction);
    EXPECT_LT(std::abs(eye.z), atrium::kColumnLine - 1.0f);  // in the central hall
    EXPECT_GT(std::abs(direction.x), 0.7f);                  // looking along it
    EXPECT_LT(direction.y, 0.0f);                            // down towards the floor's reflections
    int in_view = 0;
    for (const vec3& c : creatures) in_view += glm::dot(glm::normalize(c - eye), direction) > std::cos(glm::radians(30.0f)) ? 1 : 0;
    EXPECT_GE(in_view, 2);
  }
  vec3 eye, direction;
  frame(4400, eye, direction);
  EXPECT_GT(std::abs(eye.z), atrium::kColumnLine + 0.5f);  // in an aisle, looking elsewhere
}

TEST(Atrium, LightSweepsTheHallAtFiveMetres) {
  const Scene& scene = full_atrium();
  const LightPathSpec& light = scene.walkthrough.light;
  ASSERT_EQ(light.points.size(), 2u);
  EXPECT_GT(light.period_frames, 0);
  for (const vec3& p : light.points) {
    EXPECT_FLOAT_EQ(p.y, 5.0f);
    EXPECT_LT(std::abs(p.z), atrium::kColumnLine - 1.0f);
    EXPECT_TRUE(atrium::interior_bounds().contains(p));
  }
  EXPECT_GT(glm::distance(light.points[0], light.points[1]), 30.0f);
  EXPECT_GT(scene.light.range, 10.0f);
  EXPECT_GT(scene.light.intensity, 0.0f);
  EXPECT_GT(scene.sky_color.z, 0.0f);
}

TEST(Presets, NamesAndDispatch) {
  EXPECT_EQ(preset_names(), (std::vector<std::string>{"atrium", "atrium-simple", "sponza"}));
  for (const std::string& name : preset_names()) EXPECT_TRUE(is_preset_name(name));
  EXPECT_FALSE(is_preset_name("atrium-full"));
  EXPECT_FALSE(is_preset_name(""));
  EXPECT_THROW(make_preset("nope"), Error);
  const Scene scene = make_preset("atrium-simple");
  EXPECT_EQ(scene.name, "atrium-simple");
  EXPECT_EQ(scene.source, "built-in");
  EXPECT_EQ(scene.vertex_count(), simple_atrium().vertex_count());
}

}  // namespace
}  // namespace glint::procedural
