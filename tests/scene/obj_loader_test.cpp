#include "scene/obj_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/png_writer.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace glint {
namespace {

using testing::TempFolder;

// A 2-unit cube centred at the origin, counter-clockwise from outside, with UVs and one normal per
// face: the four side faces use "red", bottom and top "mirror".
constexpr const char* kCubeObj = R"(# test cube
mtllib cube.mtl
o cube
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 -1
vn 0 0 1
vn -1 0 0
vn 1 0 0
vn 0 -1 0
vn 0 1 0
usemtl red
f 1/1/1 4/2/1 3/3/1 2/4/1
f 5/1/2 6/2/2 7/3/2 8/4/2
f 1/1/3 5/2/3 8/3/3 4/4/3
f 2/1/4 3/2/4 7/3/4 6/4/4
usemtl mirror
f 1/1/5 2/2/5 6/3/5 5/4/5
f 4/1/6 8/2/6 7/3/6 3/4/6
)";

constexpr const char* kCubeMtl = R"(newmtl red
Kd 0.8 0.1 0.1
Ks 0.5 0.5 0.5
Ns 64
map_Kd red.png

newmtl mirror
Kd 0.9
Ks 0 0 0
Pm 0.75
Ke 0.1 0.2 0.3
)";

// The same cube with positions only: 8 shared vertices, 6 quads.
constexpr const char* kBareCubeObj = R"(v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
f 1 4 3 2
f 5 6 7 8
f 1 5 8 4
f 2 3 7 6
f 1 2 6 5
f 4 8 7 3
)";

const Mesh& mesh_named(const Scene& scene, const std::string& name) {
  const auto it = std::find_if(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) { return m.name == name; });
  if (it == scene.meshes.end()) throw std::runtime_error("no mesh named " + name);
  return *it;
}

const Material& material_named(const Scene& scene, const std::string& name) {
  const auto it = std::find_if(scene.materials.begin(), scene.materials.end(), [&](const Material& m) { return m.name == name; });
  if (it == scene.materials.end()) throw std::runtime_error("no material named " + name);
  return *it;
}

// Loads `text` written as `name` and returns the glint::Error's message ("" when it loads).
std::string load_error(const TempFolder& folder, const std::string& name, const std::string& text) {
  const std::filesystem::path file = folder.write(name, text);
  ScopedLogCapture quiet;
  try {
    load_obj(file);
  } catch (const Error& error) {
    return error.what();
  }
  return "";
}

TEST(ObjLoader, CubeWithTwoMaterialsBecomesOneMeshPerMaterial) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write("cube.obj", kCubeObj);
  folder.write("cube.mtl", kCubeMtl);
  testing::write_png(folder.path() / "red.png", 2, 2, testing::two_by_two_rgba());
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);

  EXPECT_EQ(scene.name, "cube");
  EXPECT_EQ(scene.source, obj.string());
  ASSERT_EQ(scene.meshes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  const Mesh& red = mesh_named(scene, "cube/red");
  const Mesh& mirror = mesh_named(scene, "cube/mirror");
  // 4 quads -> 8 triangles; each quad has 4 distinct (v, vt, vn) corners shared by its 2 triangles.
  EXPECT_EQ(red.triangle_count(), 8u);
  EXPECT_EQ(red.vertex_count(), 16u);
  EXPECT_EQ(mirror.triangle_count(), 4u);
  EXPECT_EQ(mirror.vertex_count(), 8u);
  EXPECT_EQ(red.uvs.size(), red.vertex_count());
  EXPECT_EQ(scene.materials[red.material].name, "red");
  EXPECT_EQ(scene.materials[mirror.material].name, "mirror");
  for (const Instance& instance : scene.instances) {
    EXPECT_EQ(instance.transform, mat4(1.0f));
    EXPECT_EQ(instance.name, scene.meshes[instance.mesh].name);
  }
  EXPECT_FALSE(scene.walkthrough.camera.points.empty());  // the default walkthrough was assigned
  EXPECT_EQ(capture.count_warnings(""), 0);

  // The file's per-face normals are kept (so corners are not merged across faces): each triangle's
  // corners carry exactly its geometric normal.
  for (const Mesh* mesh : {&red, &mirror})
    for (std::size_t t = 0; t < mesh->triangle_count(); ++t) {
      const vec3 a = mesh->positions[mesh->indices[3 * t]], b = mesh->positions[mesh->indices[3 * t + 1]],
                 c = mesh->positions[mesh->indices[3 * t + 2]];
      const vec3 face = glm::normalize(glm::cross(b - a, c - a));
      for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh->normals[mesh->indices[3 * t + k]], face) << mesh->name << " " << t;
    }
}

TEST(ObjLoader, MaterialValuesFollowTheMtlMapping) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write("cube.obj", kCubeObj);
  folder.write("cube.mtl", kCubeMtl);
  testing::write_png(folder.path() / "red.png", 2, 2, testing::two_by_two_rgba());
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.materials.size(), 2u);  // no "default": every face has a material
  const Material& red = material_named(scene, "red");
  EXPECT_EQ(red.diffuse, vec3(0.8f, 0.1f, 0.1f));
  EXPECT_EQ(red.specular, vec3(0.5f));
  EXPECT_EQ(red.specular_exponent, 64.0f);
  EXPECT_EQ(red.reflectivity, 0.0f);  // no Pm
  EXPECT_EQ(red.emissive, vec3(0.0f));
  const Material& mirror = material_named(scene, "mirror");
  EXPECT_EQ(mirror.diffuse, vec3(0.9f));  // one number: grey
  EXPECT_EQ(mirror.specular, vec3(0.0f));
  EXPECT_EQ(mirror.reflectivity, 0.75f);
  EXPECT_EQ(mirror.emissive, vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(mirror.diffuse_texture, -1);
}

TEST(ObjLoader, DiffuseTextureIsLoadedWithItsTexels) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write("cube.obj", kCubeObj);
  folder.write("cube.mtl", kCubeMtl);
  testing::write_png(folder.path() / "red.png", 2, 2, testing::two_by_two_rgba());
  const Scene scene = load_obj(obj);
  const Material& red = material_named(scene, "red");
  ASSERT_EQ(scene.textures.size(), 1u);
  ASSERT_EQ(red.diffuse_texture, 0);
  const Texture& texture = scene.textures[0];
  EXPECT_FALSE(texture.placeholder);
  EXPECT_EQ(texture.width, 2);
  EXPECT_EQ(texture.rgba, testing::two_by_two_rgba());
}

TEST(ObjLoader, SharedVerticesAreDeduplicated) {
  TempFolder folder;
  const Scene scene = load_obj(folder.write("box.obj", kBareCubeObj));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "box");  // no `o`: the file stem
  EXPECT_EQ(scene.meshes[0].vertex_count(), 8u);
  EXPECT_EQ(scene.meshes[0].triangle_count(), 12u);
  EXPECT_TRUE(scene.meshes[0].uvs.empty());  // no vt in the file
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
}

TEST(ObjLoader, MissingNormalsAreSmoothAndPointOutward) {
  TempFolder folder;
  const Scene scene = load_obj(folder.write("box.obj", kBareCubeObj));
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.normals.size(), 8u);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f);
    // Each corner's normal averages its three faces: well inside the corner's octant.
    EXPECT_GT(glm::dot(mesh.normals[v], glm::normalize(mesh.positions[v])), 0.5f) << "vertex " << v;
  }
}

TEST(ObjLoader, FlatNormalsOptionGivesExactFaceNormals) {
  TempFolder folder;
  LoadOptions options;
  options.flat_normals = true;
  const Scene scene = load_obj(folder.write("box.obj", kBareCubeObj), options);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.vertex_count(), 36u);  // three own vertices per triangle
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const vec3 centroid = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                           mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
    // The face's axis is the centroid's largest component; the normal is exactly that unit axis.
    const int axis = std::abs(centroid.x) > 0.9f ? 0 : (std::abs(centroid.y) > 0.9f ? 1 : 2);
    vec3 expected(0.0f);
    expected[axis] = centroid[axis] > 0.0f ? 1.0f : -1.0f;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.normals[mesh.indices[3 * t + k]], expected) << "triangle " << t;
  }
}

TEST(ObjLoader, NegativeIndicesCountBackFromTheLastVertex) {
  TempFolder folder;
  const Scene positive = load_obj(folder.write("positive.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                               "f 1/1 2/2 3/3\nv 1 1 0\nf 2 4 3\n"));
  const Scene negative = load_obj(folder.write("negative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                                               "f -3/-3 -2/-2 -1/-1\nv 1 1 0\nf -3 -1 -2\n"));
  ASSERT_EQ(negative.meshes.size(), positive.meshes.size());
  const Mesh& a = positive.meshes[0];
  const Mesh& b = negative.meshes[0];
  ASSERT_EQ(b.triangle_count(), 2u);
  for (std::size_t i = 0; i < a.indices.size(); ++i)
    EXPECT_EQ(b.positions[b.indices[i]], a.positions[a.indices[i]]) << "corner " << i;
  EXPECT_EQ(b.uvs, a.uvs);
  EXPECT_EQ(b.positions[b.indices[4]], vec3(1.0f, 1.0f, 0.0f));  // -1 in the second face: the 4th vertex
}

TEST(ObjLoader, ObjectsAreSplitByMaterialAndMergedAcrossRepeats) {
  TempFolder folder;
  folder.write("two.mtl", "newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n");
  const std::filesystem::path obj = folder.write(
      "two.obj",
      "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
      "o first\nusemtl a\nf 1 2 3\nusemtl b\nf 2 4 3\nusemtl a\nf 1 2 4\n"
      "o second\nusemtl b\nf 1 2 3\nf 2 4 3\n");
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(mesh_named(scene, "first/a").triangle_count(), 2u);  // both `usemtl a` runs
  EXPECT_EQ(mesh_named(scene, "first/b").triangle_count(), 1u);
  EXPECT_EQ(mesh_named(scene, "second").triangle_count(), 2u);    // one material: no suffix
  EXPECT_EQ(scene.materials[mesh_named(scene, "second").material].name, "b");
}

TEST(ObjLoader, TextureResolvesRelativeToTheMtlFolder) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write("scene.obj", "mtllib materials/look.mtl\nusemtl wall\n"
                                                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  folder.write("materials/look.mtl", "newmtl wall\nmap_Kd -s 1 1 1 tex/wall.png\n");
  testing::write_png(folder.path() / "materials/tex/wall.png", 2, 2, testing::two_by_two_rgba());
  // A decoy at the OBJ-relative path: it must not be the one found.
  testing::write_png(folder.path() / "tex/wall.png", 1, 1, {9, 9, 9, 255});
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_FALSE(scene.textures[0].placeholder);
  EXPECT_EQ(scene.textures[0].rgba, testing::two_by_two_rgba());
}

TEST(ObjLoader, TextureNameIsMatchedIgnoringCaseAndBackslashes) {
  TempFolder folder;
  const std::filesystem::path obj =
      folder.write("scene.obj", "mtllib scene.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  folder.write("scene.mtl", "newmtl wall\nmap_Kd Textures\\WALL.PNG\n");
  testing::write_png(folder.path() / "textures/wall.png", 2, 2, testing::two_by_two_rgba());
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_FALSE(scene.textures[0].placeholder);
  EXPECT_EQ(scene.textures[0].rgba, testing::two_by_two_rgba());
  EXPECT_EQ(capture.count_warnings(""), 0);
}

TEST(ObjLoader, TextureSharedByMaterialsIsLoadedOnce) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write(
      "scene.obj", "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n");
  folder.write("scene.mtl", "newmtl a\nmap_Kd wall.png\nnewmtl b\nKd 0.5 0.5 0.5\nmap_Kd ./WALL.png\n");
  testing::write_png(folder.path() / "wall.png", 2, 2, testing::two_by_two_rgba());
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_EQ(material_named(scene, "a").diffuse_texture, 0);
  EXPECT_EQ(material_named(scene, "b").diffuse_texture, 0);
}

TEST(ObjLoader, MissingTextureGivesPlaceholderAndWarning) {
  TempFolder folder;
  const std::filesystem::path obj =
      folder.write("scene.obj", "mtllib scene.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  folder.write("scene.mtl", "# wall\nnewmtl wall\nKd 1 1 1\nmap_Kd absent.png\n");
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.textures.size(), 1u);
  EXPECT_TRUE(scene.textures[0].placeholder);
  EXPECT_EQ(material_named(scene, "wall").diffuse_texture, 0);
  EXPECT_EQ(capture.count_warnings("scene.mtl:4:"), 1);
  EXPECT_EQ(capture.count_warnings("absent.png"), 1);
}

TEST(ObjLoader, MissingMtlIsAWarningAndTheDefaultMaterial) {
  TempFolder folder;
  const std::filesystem::path obj =
      folder.write("scene.obj", "# no library\nmtllib absent.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "default");
  EXPECT_EQ(scene.meshes[0].material, 0u);
  EXPECT_EQ(capture.count_warnings("scene.obj:2:"), 1);
  EXPECT_EQ(capture.count_warnings("absent.mtl"), 1);
}

TEST(ObjLoader, MtllibLineCanNameSeveralLibraries) {
  TempFolder folder;
  folder.write("a.mtl", "newmtl from_a\nKd 1 0 0\n");
  folder.write("B.MTL", "newmtl from_b\nKd 0 1 0\n");  // named "b.mtl" in the OBJ: found ignoring case
  const std::filesystem::path obj = folder.write(
      "scene.obj", "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl from_a\nf 1 2 3\nusemtl from_b\nf 1 3 2\n");
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  EXPECT_EQ(capture.count_warnings(""), 0);
  EXPECT_EQ(material_named(scene, "from_a").diffuse, vec3(1, 0, 0));
  EXPECT_EQ(material_named(scene, "from_b").diffuse, vec3(0, 1, 0));
}

TEST(ObjLoader, UsemtlAboveTheMtllibLineStillFindsItsMaterial) {
  TempFolder folder;
  folder.write("late.mtl", "newmtl wall\nKd 0 0 1\n");
  const std::filesystem::path obj =
      folder.write("late.obj", "usemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nmtllib late.mtl\n");
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[scene.meshes[0].material].name, "wall");
  EXPECT_EQ(capture.count_warnings(""), 0);
}

TEST(ObjLoader, UnknownMaterialNameIsAWarningAndTheDefaultMaterial) {
  TempFolder folder;
  folder.write("scene.mtl", "newmtl known\nKd 0 0 1\n");
  const std::filesystem::path obj = folder.write(
      "scene.obj", "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl known\nf 1 2 3\nusemtl typo\nf 1 3 2\n");
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(scene.materials[1].name, "default");  // after the library's materials
  EXPECT_EQ(scene.materials[mesh_named(scene, "scene/default").material].name, "default");
  EXPECT_EQ(capture.count_warnings("scene.obj:7:"), 1);
  EXPECT_EQ(capture.count_warnings("'typo'"), 1);
}

TEST(ObjLoader, DegenerateTrianglesAreDroppedWithOneWarning) {
  TempFolder folder;
  const std::filesystem::path obj = folder.write("flat.obj",
                                                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\n"
                                                 "f 1 2 3\n"   // fine
                                                 "f 1 1 2\n"   // repeated vertex
                                                 "f 1 2 4\n"); // collinear
  ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  EXPECT_EQ(scene.triangle_count(), 1u);
  EXPECT_EQ(capture.count_warnings("degenerate"), 1);
  EXPECT_EQ(capture.count_warnings("dropped 2 degenerate"), 1);
  EXPECT_EQ(capture.count_warnings("flat.obj"), 1);
}

TEST(ObjLoader, OnlyDegenerateTrianglesIsAnEmptySceneError) {
  TempFolder folder;
  EXPECT_NE(load_error(folder, "line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n").find("empty"), std::string::npos);
}

TEST(ObjLoader, MissingFileIsAnErrorNamingIt) {
  TempFolder folder;
  const std::filesystem::path missing = folder.path() / "nowhere.obj";
  try {
    load_obj(missing);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(missing.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos) << error.what();
  }
}

TEST(ObjLoader, UnreadableFileIsAnErrorNamingIt) {
  TempFolder folder;
  std::filesystem::create_directories(folder.path() / "folder.obj");  // exists, but cannot be read as a file
  try {
    load_obj(folder.path() / "folder.obj");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("folder.obj: cannot read"), std::string::npos) << error.what();
  }
}

// Bad input: the message names the file and the line ("bad.obj:LINE:") and says what is wrong.
struct BadObjCase {
  const char* label;
  const char* text;
  int line;
  const char* problem;  // a phrase of the message
};

void PrintTo(const BadObjCase& c, std::ostream* out) { *out << c.label; }

class ObjLoaderBadInput : public ::testing::TestWithParam<BadObjCase> {};

TEST_P(ObjLoaderBadInput, IsOneErrorNamingFileAndLine) {
  TempFolder folder;
  const BadObjCase& bad = GetParam();
  const std::string message = load_error(folder, "bad.obj", bad.text);
  ASSERT_FALSE(message.empty()) << "loaded without an error";
  EXPECT_NE(message.find("bad.obj:" + std::to_string(bad.line) + ":"), std::string::npos) << message;
  EXPECT_NE(message.find(bad.problem), std::string::npos) << message;
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3

INSTANTIATE_TEST_SUITE_P(
    ObjLoader, ObjLoaderBadInput,
    ::testing::Values(
        BadObjCase{"NonNumericPosition", "v 0 0 0\nv 1 0 0\nv 0 x 0\nf 1 2 3\n", 3, "'x' is not a number"},
        BadObjCase{"TooFewPositionNumbers", "v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", 2, "has 2 numbers"},
        BadObjCase{"NanPosition", "# comment\nv 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 3, "not a finite number"},
        BadObjCase{"InfinitePosition", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n", 3, "not a finite number"},
        BadObjCase{"OverflowingPosition", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", 2, "not a finite number"},
        BadObjCase{"NonNumericTexcoord", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 o.5\nf 1 2 3\n", 4, "'o.5' is not a number"},
        BadObjCase{"EmptyTexcoord", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt\nf 1 2 3\n", 4, "has 0 numbers"},
        BadObjCase{"TooFewNormalNumbers", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nvn 0 1\nf 1 2 3\n", 5, "has 2 numbers"},
        BadObjCase{"NonNumericNormal", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 1 z\nf 1 2 3\n", 4, "'z' is not a number"},
        BadObjCase{"ZeroFaceIndex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, "index 0"},
        BadObjCase{"FaceIndexPastTheEnd", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n", 5, "position 4 is out of range"},
        BadObjCase{"ForwardFaceIndex", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n", 3, "position 3 is out of range"},
        BadObjCase{"RelativeIndexBeforeTheStart", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4, "index -4 is out of range"},
        BadObjCase{"TexcoordIndexOutOfRange", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n", 5,
                   "texture coordinate 2 is out of range"},
        BadObjCase{"NormalIndexOutOfRange", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n", 5,
                   "normal 7 is out of range"},
        BadObjCase{"EmptyTexcoordIndex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/ 3/1\n", 5,
                   "empty texture coordinate index"},
        BadObjCase{"TooManySlashes", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n", 4, "not a vertex reference"},
        BadObjCase{"UsemtlWithoutName", "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n", 4, "needs a material name"},
        BadObjCase{"NonNumericFaceIndex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 three\n", 4, "not an integer index"},
        BadObjCase{"FaceWithTwoVertices", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", 5, "at least 3"},
        BadObjCase{"FaceWithNoVertices", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\n", 4, "at least 3"},
        BadObjCase{"WindowsLineEndings", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\nf 1 2 0\r\n", 5, "index 0"}),
    [](const ::testing::TestParamInfo<BadObjCase>& param_info) { return std::string(param_info.param.label); });

TEST(ObjLoader, NoFacesIsAnErrorNamingTheFile) {
  TempFolder folder;
  const std::string message = load_error(folder, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_NE(message.find("points.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("no faces"), std::string::npos) << message;
}

TEST(ObjLoader, EmptyFileIsAnError) {
  TempFolder folder;
  EXPECT_NE(load_error(folder, "empty.obj", "").find("no faces"), std::string::npos);
}

TEST(ObjLoader, MalformedMtlIsAnErrorNamingTheMtlFileAndLine) {
  TempFolder folder;
  folder.write("look.mtl", "newmtl wall\n\nKd 0.5 abc 1\n");
  const std::string message =
      load_error(folder, "scene.obj", "mtllib look.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message.find("look.mtl:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("'abc' is not a number"), std::string::npos) << message;
}

TEST(ObjLoader, MtlStatementBeforeNewmtlIsAnError) {
  TempFolder folder;
  folder.write("look.mtl", "# header\nNs 10\nnewmtl wall\n");
  const std::string message =
      load_error(folder, "scene.obj", "mtllib look.mtl\nusemtl wall\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(message.find("look.mtl:2:"), std::string::npos) << message;
  EXPECT_NE(message.find("before any 'newmtl'"), std::string::npos) << message;
}

TEST(ObjLoader, BinaryFileIsAnError) {
  TempFolder folder;
  const std::string message = load_error(folder, "binary.obj", std::string("v 0 0 0\n\x01\x00\x02", 11));
  EXPECT_NE(message.find("binary.obj:2:"), std::string::npos) << message;
}

TEST(ObjLoader, FacesWithoutUvsInAMeshWithUvsGetZeroUvs) {
  TempFolder folder;
  const Scene scene = load_obj(folder.write("mixed.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.25\n"
                                                         "f 1/1 2/1 3/1\nf 2 4 3\n"));
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.uvs.size(), mesh.vertex_count());
  EXPECT_EQ(mesh.uvs[mesh.indices[0]], vec2(0.5f, 0.25f));
  EXPECT_EQ(mesh.uvs[mesh.indices[4]], vec2(0.0f));  // vertex 4 only appears without a vt
}

}  // namespace
}  // namespace glint
