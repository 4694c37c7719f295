#include "scene/procedural/atrium.h"

#include "core/log.h"
#include "scene/procedural/atrium_architecture.h"
#include "scene/procedural/atrium_layout.h"
#include "scene/procedural/atrium_walkthrough.h"
#include "scene/procedural/creatures.h"
#include "scene/procedural/textures.h"
#include "scene/specular_roughness.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <string>

namespace glint::procedural {
namespace {

constexpr int kTextureSize = 512;  // like the paper's textures

// Meshes the creatures of one kind in placement order. The first searches the grid resolution for
// its vertex target; its siblings start from that cell size scaled by their relative size, which
// usually hits the target with one mesh.
template <typename Pose>
class CreatureMesher {
public:
  CreatureMesher(Pose (*pose_of)(int), BlendedShape (*shape_of)(const Pose&), std::size_t target_vertices,
                 std::uint32_t material, const char* name_prefix)
      : pose_of_(pose_of), shape_of_(shape_of), target_vertices_(target_vertices), material_(material),
        name_prefix_(name_prefix) {}

  Mesh next(int variant) {
    const Pose pose = pose_of_(variant);
    const float reference_scale = pose_of_(0).scale;
    const std::string name = name_prefix_ + "-" + std::to_string(count_++);
    CreatureMesh result = creature_mesh(shape_of_(pose), target_vertices_, name, first_cell_ * pose.scale / reference_scale);
    if (first_cell_ == 0.0f) first_cell_ = result.cell_size * reference_scale / pose.scale;
    result.mesh.material = material_;
    return std::move(result.mesh);
  }

private:
  Pose (*pose_of_)(int);
  BlendedShape (*shape_of_)(const Pose&);
  std::size_t target_vertices_;
  std::uint32_t material_;
  std::string name_prefix_;
  float first_cell_ = 0.0f;
  int count_ = 0;
};

std::uint32_t add_material(Scene& scene, Material material) {
  scene.materials.push_back(std::move(material));
  return static_cast<std::uint32_t>(scene.materials.size() - 1);
}

int add_texture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return static_cast<int>(scene.textures.size() - 1);
}

Material textured(const std::string& name, int texture, float specular, float exponent, float reflectivity = 0.0f,
                  float roughness = 0.0f) {
  Material m;
  m.name = name;
  m.diffuse = vec3(1.0f);
  m.diffuse_texture = texture;
  m.specular = vec3(specular);
  m.specular_exponent = exponent;
  m.reflectivity = reflectivity;
  m.roughness = roughness;
  return m;
}

ArchitectureMaterials add_building_materials(Scene& scene) {
  ArchitectureMaterials m;
  // The polished floor is the one strongly reflective surface, as in the paper; glossy reflections
  // (docs/glossy.md) get a range of roughness besides it: the gallery floor's honed stone and the
  // balustrade's brushed metal.
  m.marble = add_material(scene, textured("marble-floor", add_texture(scene, make_marble_texture(kTextureSize)), 0.5f, 96.0f, 0.5f, 0.06f));
  const int stone_texture = add_texture(scene, make_stone_texture(kTextureSize));
  m.stone = add_material(scene, textured("stone", stone_texture, 0.05f, 16.0f));
  m.brick = add_material(scene, textured("brick", add_texture(scene, make_brick_texture(kTextureSize)), 0.03f, 8.0f));
  m.plaster = add_material(scene, textured("plaster", add_texture(scene, make_plaster_texture(kTextureSize)), 0.02f, 8.0f));
  m.wood = add_material(scene, textured("wood", add_texture(scene, make_wood_texture(kTextureSize)), 0.15f, 32.0f));
  m.fabric_red = add_material(scene, textured("fabric-red", add_texture(scene, make_fabric_texture(kTextureSize, vec3(0.62f, 0.09f, 0.08f), vec3(0.85f, 0.68f, 0.25f), 71u)), 0.02f, 4.0f));
  m.fabric_blue = add_material(scene, textured("fabric-blue", add_texture(scene, make_fabric_texture(kTextureSize, vec3(0.10f, 0.18f, 0.48f), vec3(0.88f, 0.82f, 0.60f), 72u)), 0.02f, 4.0f));
  m.polished_stone = add_material(scene, textured("polished-stone", stone_texture, 0.1f, 24.0f, 0.2f, 0.35f));
  Material metal;
  metal.name = "bronze";
  metal.diffuse = vec3(0.30f, 0.20f, 0.11f);
  metal.specular = vec3(0.75f, 0.55f, 0.35f);
  metal.specular_exponent = specular_exponent_from_roughness(0.25f);
  metal.reflectivity = 0.45f;  // below the floor's: the marble stays the strongest mirror, as in the paper
  metal.roughness = 0.25f;
  m.metal = add_material(scene, metal);
  return m;
}

void add_creatures(Scene& scene, AtriumDetail detail) {
  Material armadillo;
  armadillo.name = "armadillo-skin";
  armadillo.diffuse = vec3(0.58f, 0.50f, 0.40f);
  armadillo.specular = vec3(0.25f);
  armadillo.specular_exponent = 48.0f;
  const std::uint32_t armadillo_material = add_material(scene, armadillo);
  Material dinosaur;
  dinosaur.name = "dinosaur-skin";
  dinosaur.diffuse = vec3(0.32f, 0.42f, 0.24f);
  dinosaur.specular = vec3(0.15f);
  dinosaur.specular_exponent = 24.0f;
  const std::uint32_t dinosaur_material = add_material(scene, dinosaur);

  const AtriumCounts targets = atrium_creature_targets(detail);
  CreatureMesher<ArmadilloPose> armadillos(armadillo_pose, armadillo_shape, targets.armadillo_vertices,
                                           armadillo_material, kArmadilloPrefix);
  CreatureMesher<DinosaurPose> dinosaurs(dinosaur_pose, dinosaur_shape, targets.dinosaur_vertices, dinosaur_material,
                                         kDinosaurPrefix);
  for (const atrium::CreaturePlacement& placement : atrium::creature_placements()) {
    Mesh mesh;
    if (placement.kind == atrium::CreaturePlacement::Kind::dinosaur) {
      mesh = dinosaurs.next(placement.variant);
      mesh.deformable = true;
      mesh.deform = dinosaur_deform(dinosaur_pose(placement.variant));
    } else {
      mesh = armadillos.next(placement.variant);
    }
    const mat4 transform = glm::rotate(glm::translate(mat4(1.0f), vec3(placement.position.x, 0.0f, placement.position.y)),
                                       glm::radians(placement.yaw_degrees), vec3(0, 1, 0));
    scene.instances.push_back(Instance{mesh.name, static_cast<std::uint32_t>(scene.meshes.size()), transform});
    scene.meshes.push_back(std::move(mesh));
  }
}

}  // namespace

AtriumCounts atrium_creature_targets(AtriumDetail detail) {
  // The paper's counts: 35k / 20k vertices, simplified to 3.5k / 7.5k.
  return detail == AtriumDetail::full ? AtriumCounts{35000, 20000} : AtriumCounts{3500, 7500};
}

Scene make_atrium(AtriumDetail detail) {
  const auto start = std::chrono::steady_clock::now();
  Scene scene;
  scene.name = detail == AtriumDetail::full ? "atrium" : "atrium-simple";
  scene.source = "built-in";
  const ArchitectureMaterials materials = add_building_materials(scene);
  add_atrium_architecture(scene, materials, ArchitectureDetail{});
  add_creatures(scene, detail);
  scene.light = atrium_light();
  scene.walkthrough = atrium_walkthrough();
  scene.sky_color = vec3(0.58f, 0.70f, 0.88f);  // the courtyard's open roof
  // The paper's distance fade, given outright as a scene file may: the size rule
  // (render/scene_reflection_fade.h) comes within 0.2 % of it, but the paper's reproduction keeps
  // the paper's numbers to the bit.
  scene.reflection_fade = DistanceFade{15.0f, 30.0f};
  scene.validate();
  log_info("{}: {} vertices, {} triangles, {} meshes, {} textures in {:.2f} s", scene.name, scene.vertex_count(),
           scene.triangle_count(), scene.meshes.size(), scene.textures.size(),
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return scene;
}

}  // namespace glint::procedural
