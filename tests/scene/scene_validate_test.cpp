// Scene::validate is the last step of every loader: each kind of broken scene must be refused with a
// message naming the source and what is wrong.
#include "core/error.h"
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <limits>

namespace glint {
namespace {

Scene one_triangle_scene() {
  Scene scene;
  scene.source = "test.scene.json";
  Mesh mesh;
  mesh.name = "tri";
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  scene.materials.push_back(Material{});
  scene.instances.push_back(Instance{"tri", 0, mat4(1.0f)});
  scene.walkthrough.camera.points = {{0, 0, 5}, {1, 0, 5}};
  return scene;
}

std::string validation_error(const Scene& scene) {
  try {
    scene.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(SceneValidate, AcceptsAWellFormedScene) { EXPECT_EQ(validation_error(one_triangle_scene()), ""); }

TEST(SceneValidate, CountsAndBoundsAreTotalsOverInstances) {
  Scene scene = one_triangle_scene();
  scene.instances.push_back(Instance{"moved", 0, glm::mat4(1.0f)});
  scene.instances.back().transform[3] = vec4(10, 0, 0, 1);
  EXPECT_EQ(scene.vertex_count(), 6u);
  EXPECT_EQ(scene.triangle_count(), 2u);
  EXPECT_EQ(scene.world_bounds().max, vec3(11, 1, 0));
  EXPECT_EQ(scene.world_bounds().min, vec3(0, 0, 0));
}

TEST(SceneValidate, RefusesAnEmptyScene) {
  Scene scene = one_triangle_scene();
  scene.instances.clear();
  EXPECT_NE(validation_error(scene).find("test.scene.json: the scene is empty"), std::string::npos);
}

TEST(SceneValidate, RefusesAnOutOfRangeIndex) {
  Scene scene = one_triangle_scene();
  scene.meshes[0].indices[2] = 3;
  const std::string message = validation_error(scene);
  EXPECT_NE(message.find("mesh 'tri': triangle 0 uses vertex 3 but the mesh has 3 vertices"), std::string::npos) << message;
}

TEST(SceneValidate, RefusesNonFinitePositionsAndNormals) {
  Scene scene = one_triangle_scene();
  scene.meshes[0].positions[1].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(validation_error(scene).find("vertex 1 has a non-finite position"), std::string::npos);
  scene = one_triangle_scene();
  scene.meshes[0].normals[2].x = std::numeric_limits<float>::infinity();
  EXPECT_NE(validation_error(scene).find("vertex 2 has a non-finite normal"), std::string::npos);
}

TEST(SceneValidate, RefusesDanglingMaterialTextureAndMeshReferences) {
  Scene scene = one_triangle_scene();
  scene.meshes[0].material = 4;
  EXPECT_NE(validation_error(scene).find("material 4 out of range"), std::string::npos);
  scene = one_triangle_scene();
  scene.materials[0].diffuse_texture = 0;
  EXPECT_NE(validation_error(scene).find("texture 0 out of range"), std::string::npos);
  scene = one_triangle_scene();
  scene.instances.push_back(Instance{"ghost", 7, mat4(1.0f)});
  EXPECT_NE(validation_error(scene).find("instance 'ghost': mesh 7 out of range"), std::string::npos);
}

TEST(SceneValidate, RefusesADeformableMeshWithoutDeformerAndABadWalkthrough) {
  Scene scene = one_triangle_scene();
  scene.meshes[0].deformable = true;
  EXPECT_NE(validation_error(scene).find("deformable but has no deformer"), std::string::npos);
  scene = one_triangle_scene();
  scene.walkthrough.camera.points = {{0, 0, 5}};
  const std::string message = validation_error(scene);
  EXPECT_NE(message.find("test.scene.json: "), std::string::npos) << message;
  EXPECT_NE(message.find("camera"), std::string::npos) << message;
}

TEST(SceneValidate, RefusesInstanceTransformsTheRayTracersCannotUseNamingTheSceneFile) {
  // These reached the acceleration structures and failed there as "accel: ..." with no file named.
  {
    Scene scene = one_triangle_scene();
    scene.instances[0].transform = glm::scale(mat4(1.0f), vec3(1e-30f));  // determinant 1e-90: 0 in float
    const std::string message = validation_error(scene);
    EXPECT_NE(message.find("test.scene.json: instance 'tri': the transform cannot be inverted in float"),
              std::string::npos) << message;
  }
  {
    Scene scene = one_triangle_scene();
    scene.instances[0].transform = glm::scale(mat4(1.0f), vec3(1e-13f));  // invertible, inverse 1e39 is not finite
    EXPECT_NE(validation_error(scene).find("cannot be inverted in float"), std::string::npos);
  }
  {
    Scene scene = one_triangle_scene();
    scene.instances[0].transform[0][1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(validation_error(scene).find("test.scene.json: instance 'tri': the transform is not finite"),
              std::string::npos);
  }
  {
    Scene scene = one_triangle_scene();
    scene.meshes[0].positions[1] = vec3(3e38f, 0, 0);
    scene.instances[0].transform = glm::scale(mat4(1.0f), vec3(10.0f));  // 3e39: past float
    const std::string message = validation_error(scene);
    EXPECT_NE(message.find("test.scene.json: instance 'tri': vertex 1 of mesh 'tri' is not finite after the "
                           "instance transform"),
              std::string::npos) << message;
  }
  {
    Scene scene = one_triangle_scene();
    scene.instances[0].transform = glm::scale(mat4(1.0f), vec3(1e30f));  // determinant 1e90: inf, inverse all zero
    EXPECT_NE(validation_error(scene).find("cannot be inverted in float"), std::string::npos);
  }
  for (const float scale : {1e-9f, 1e9f}) {  // large or small but invertible worlds stay valid
    Scene scene = one_triangle_scene();
    scene.instances[0].transform = glm::scale(mat4(1.0f), vec3(scale));
    EXPECT_EQ(validation_error(scene), "") << scale;
  }
}

TEST(SceneValidate, NamesFromFilesAreShownEscapedAndBounded) {
  Scene scene = one_triangle_scene();
  scene.instances[0].name = std::string(5'000'000, 'n') + "\x1b[31m";
  scene.instances[0].mesh = 7;
  const std::string message = validation_error(scene);
  EXPECT_LT(message.size(), 500u);
  EXPECT_NE(message.find("(5000005 bytes in all)"), std::string::npos);
  EXPECT_EQ(message.find('\x1b'), std::string::npos);
}

}  // namespace
}  // namespace glint
