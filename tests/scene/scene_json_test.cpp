#include "scene/scene_json_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/append_scene.h"
#include "scene/assets_dir.h"
#include "scene/gltf_test_builder.h"
#include "scene/json_field.h"
#include "scene/load_scene.h"
#include "scene/scene_json_builder.h"
#include "scene/scene_json_parser.h"
#include "support/error_of.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "support/test_paths.h"

#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

namespace glint {
namespace {

using testing::GltfBuilder;
using testing::TempFolder;
using testing::ScopedEnv;
using testing::error_of;
using nlohmann::json;

// A one-triangle glTF (vertices (0,0,0), (1,0,0), (0,1,0)) whose material is called `material`, plus a
// degenerate triangle so that every load logs exactly one "degenerate" warning (counts loads).
std::string triangle_gltf(const std::string& material) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int indices = gltf.add_indices_u16({0, 1, 2, 0, 0, 1});
  gltf.json["materials"].push_back({{"name", material}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"indices", indices}, {"material", 0}});
  return gltf.gltf_text();
}


std::string parse_error(const std::string& text) {
  return error_of([&] { parse_scene_description(text, "scene.json"); });
}

vec3 apply(const mat4& m, const vec3& p) { return vec3(m * vec4(p, 1.0f)); }

void expect_near(const vec3& actual, const vec3& expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f);
  EXPECT_NEAR(actual.y, expected.y, 1e-5f);
  EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}


// ---- parsing (no mesh file is read) ----

TEST(SceneJsonParse, TransformScalesThenRotatesXThenYThenZThenTranslates) {
  const SceneDescription description = parse_scene_description(R"({
    "meshes": [{ "file": "a.gltf", "transform": { "translate": [10, 0, 0], "rotate": [90, 90, 0], "scale": 2 } },
               { "file": "a.gltf", "transform": { "scale": [1, 2, 3] } }]})", "scene.json");
  const mat4 m = description.meshes[0].transform.matrix();
  // (0, 1, 0): scaled to (0, 2, 0); about X by 90 to (0, 0, 2); about Y by 90 to (2, 0, 0); moved: (12, 0, 0).
  // (Y first, then X would give (0, 0, 2) -> ... a different point, so the order is observable.)
  expect_near(apply(m, vec3(0.0f, 1.0f, 0.0f)), vec3(12.0f, 0.0f, 0.0f));
  // (1, 0, 0): scaled (2, 0, 0); X leaves it; Y by 90 takes it to (0, 0, -2); moved: (10, 0, -2).
  expect_near(apply(m, vec3(1.0f, 0.0f, 0.0f)), vec3(10.0f, 0.0f, -2.0f));
  expect_near(apply(description.meshes[1].transform.matrix(), vec3(1.0f)), vec3(1.0f, 2.0f, 3.0f));
}

TEST(SceneJsonParse, ReadsEveryBlockWithDefaults) {
  const SceneDescription description = parse_scene_description(R"({
    "assets": "../models",
    "meshes": [{ "file": "fish.glb", "name": "nemo",
                 "material": { "reflectivity": 0.25, "diffuse": [1, 0, 0], "specular_exponent": 8 },
                 "deform": { "type": "sine", "axis": "z", "along": "y", "amplitude": 0.3, "frequency": 2, "speed": 5 } },
               { "file": "plain.gltf" }],
    "light": { "path": [[0, 5, 0], [10, 5, 0]], "intensity": 30 },
    "camera": { "path": [[0, 1, 0], [1, 1, 0], [2, 1, 1]], "targets": [[0, 0, 5], [1, 0, 5]], "fov_y_degrees": 45 },
    "frames": 120, "fps": 24, "sky_color": [0, 0, 0],
    "floor": { "materials": ["ground"], "reflectivity": 0.7 }})", "dir/demo.scene.json");
  EXPECT_EQ(description.name, "demo");
  EXPECT_EQ(description.assets, std::filesystem::path("../models"));
  ASSERT_EQ(description.meshes.size(), 2u);
  const MeshEntry& fish = description.meshes[0];
  EXPECT_EQ(fish.name, "nemo");
  EXPECT_EQ(fish.json_pointer, "/meshes/0");
  EXPECT_EQ(fish.material.reflectivity, 0.25f);
  EXPECT_EQ(fish.material.diffuse, vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(fish.material.specular_exponent, 8.0f);
  EXPECT_FALSE(fish.material.roughness.has_value());
  ASSERT_TRUE(fish.deform.has_value());
  EXPECT_EQ(fish.deform->displace_axis, 2);
  EXPECT_EQ(fish.deform->wave_axis, 1);
  EXPECT_FLOAT_EQ(fish.deform->amplitude, 0.3f);
  EXPECT_FLOAT_EQ(fish.deform->frequency, 2.0f);
  EXPECT_FLOAT_EQ(fish.deform->speed, 5.0f);
  EXPECT_EQ(description.meshes[1].name, "plain");  // the file's stem
  EXPECT_FALSE(description.meshes[1].deform.has_value());
  ASSERT_TRUE(description.light.has_value());
  EXPECT_FLOAT_EQ(description.light->intensity, 30.0f);
  EXPECT_FLOAT_EQ(description.light->range, 10.0f);       // default
  EXPECT_EQ(description.light->period_frames, 980);       // default
  ASSERT_TRUE(description.camera.has_value());
  EXPECT_EQ(description.camera->points.size(), 3u);
  EXPECT_EQ(description.camera->targets.size(), 2u);
  EXPECT_FLOAT_EQ(description.camera->fov_y_degrees, 45.0f);
  EXPECT_EQ(description.frames, 120);
  EXPECT_FLOAT_EQ(description.frames_per_second, 24.0f);
  EXPECT_EQ(description.sky_color, vec3(0.0f));
  ASSERT_TRUE(description.floor.has_value());
  EXPECT_EQ(description.floor->materials, std::vector<std::string>{"ground"});
  EXPECT_FLOAT_EQ(description.floor->reflectivity, 0.7f);

  const SceneDescription minimal = parse_scene_description(R"({"meshes": [{"file": "a.obj"}]})", "m.scene.json");
  EXPECT_EQ(minimal.frames, 4900);
  EXPECT_FALSE(minimal.light || minimal.camera || minimal.floor || minimal.assets);
}

TEST(SceneJsonParse, UnknownKeyNamesItsPathAndTheKeysExpected) {
  EXPECT_EQ(parse_error(R"({"meshes": [{"file": "a.obj"}, {"file": "b.obj"},
                                       {"file": "c.obj", "transfrom": {}}]})"),
            "scene.json: /meshes/2/transfrom: unknown key (expected one of: file, name, transform, material, deform)");
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "lights": {}})").find("scene.json: /lights: unknown key"),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj", "deform": {"type": "sine", "ampltude": 1}}]})")
                .find("/meshes/0/deform/ampltude: unknown key"),
            std::string::npos);
}

TEST(SceneJsonParse, MalformedJsonReportsLineAndColumn) {
  // Line 2 lacks its comma: the parser stops on line 3 at the end of the unexpected "frames" (column 10).
  const std::string message = parse_error("{\n  \"meshes\": [{\"file\": \"a.obj\"}]\n  \"frames\": 10\n}");
  EXPECT_EQ(message.rfind("scene.json:3:10: malformed JSON: syntax error", 0), 0u) << message;
  // An overflowing number has no position from the parser; it is found in the text.
  EXPECT_EQ(parse_error("{\"meshes\": [],\n \"fps\": 1e999}"),
            "scene.json:2:9: malformed JSON: number overflow parsing '1e999'");
  EXPECT_EQ(message.find("[json.exception"), std::string::npos) << message;
}

TEST(SceneJsonParse, TextPositionCountsLinesAndColumnsFromOne) {
  const TextPosition start = text_position("ab\ncd", 0);
  EXPECT_EQ(start.line, 1u);
  EXPECT_EQ(start.column, 1u);
  const TextPosition d = text_position("ab\ncd", 4);
  EXPECT_EQ(d.line, 2u);
  EXPECT_EQ(d.column, 2u);
}

TEST(SceneJsonParse, RejectsBadValuesWithTheirJsonPath) {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"meshes": [{"file": 3}]})", "scene.json: /meshes/0/file: expected a string, got number"},
      {R"({"meshes": [{"name": "x"}]})", "scene.json: /meshes/0: missing required key \"file\""},
      {R"({"frames": 3})", "scene.json: /: missing required key \"meshes\""},
      {R"({"meshes": []})", "scene.json: /meshes: the scene has no meshes"},
      {R"({"meshes": [{"file": "a.ply"}]})", "scene.json: /meshes/0/file: unsupported mesh file \"a.ply\""},
      {R"({"meshes": [{"file": "a.obj", "deform": {"type": "sine", "axis": "w"}}]})",
       "scene.json: /meshes/0/deform/axis: unknown axis \"w\" (expected \"x\", \"y\" or \"z\")"},
      {R"({"meshes": [{"file": "a.obj", "deform": {"type": "twist"}}]})", "/meshes/0/deform/type: unknown deformer"},
      {R"({"meshes": [{"file": "a.obj", "deform": {"axis": "x"}}]})", "/meshes/0/deform: missing required key \"type\""},
      {R"({"meshes": [{"file": "a.obj", "transform": {"translate": [1, 1e300, 0]}}]})",
       "scene.json: /meshes/0/transform/translate/1: expected a finite number"},
      {R"({"meshes": [{"file": "a.obj", "transform": {"scale": "big"}}]})",
       "/meshes/0/transform/scale: expected a number or [x, y, z], got string"},
      {R"({"meshes": [{"file": "a.obj", "transform": {"rotate": [1, 2]}}]})",
       "/meshes/0/transform/rotate: expected [x, y, z], got an array of 2"},
      {R"({"meshes": [{"file": "a.obj", "material": {"reflectivity": 1.5}}]})",
       "/meshes/0/material/reflectivity: 1.5 is out of range (expected 0 to 1)"},
      {R"({"meshes": [{"file": "a.obj"}], "frames": 0})", "scene.json: /frames: frames must be > 0, got 0"},
      {R"({"meshes": [{"file": "a.obj"}], "frames": 2.5})", "scene.json: /frames: expected a whole number, got 2.5"},
      {R"({"meshes": [{"file": "a.obj"}], "camera": {"path": [[0, 0, 0]]}})",
       "scene.json: /camera/path: the camera path needs at least 2 points, got 1"},
      {R"({"meshes": [{"file": "a.obj"}], "camera": {"targets": [[0, 0, 0], [1, 1, 1]]}})",
       "scene.json: /camera: missing required key \"path\""},
      {R"({"meshes": [{"file": "a.obj"}], "light": {"intensity": 3}})",
       "scene.json: /light: the light needs a \"position\" or a \"path\""},
      {R"({"meshes": [{"file": "a.obj"}], "floor": {"materials": "sp_00_pod", "reflectivity": 0.5}})",
       "scene.json: /floor/materials: expected an array, got string"},
      {R"([1, 2])", "scene.json: /: expected an object, got array"},
  };
  for (const Case& c : cases) {
    const std::string message = parse_error(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << "got:      " << message << "\nexpected: " << c.expected;
  }
}

// ---- building (glTF files on disk) ----

TEST(SceneJson, PlacesEntriesAppliesOverridesDeformAndFloor) {
  TempFolder folder;
  folder.write("models/tri.gltf", triangle_gltf("ground"));
  const Scene scene = load_scene_json_text(R"({
    "meshes": [
      { "file": "models/tri.gltf", "name": "floor", "transform": { "translate": [0, 0, 5] } },
      { "file": "models/tri.gltf", "name": "shiny", "material": { "reflectivity": 0.9, "diffuse": [0, 1, 0] } },
      { "file": "models/tri.gltf", "name": "wave",
        "deform": { "type": "sine", "axis": "x", "along": "y", "amplitude": 0.5, "frequency": 3, "speed": 1 } }],
    "floor": { "materials": ["ground"], "reflectivity": 0.4 }})",
                                           folder.path() / "demo.scene.json");
  EXPECT_EQ(scene.name, "demo");
  EXPECT_EQ(scene.source, (folder.path() / "demo.scene.json").string());
  ASSERT_EQ(scene.instances.size(), 3u);
  ASSERT_EQ(scene.meshes.size(), 3u);  // different overrides or a deformer: no sharing here

  const Instance& placed = scene.instances[0];
  EXPECT_EQ(placed.name, "floor/nodes[0]");
  expect_near(apply(placed.transform, scene.meshes[placed.mesh].positions[1]), vec3(1.0f, 0.0f, 5.0f));

  const Material& shiny = scene.materials[scene.meshes[scene.instances[1].mesh].material];
  EXPECT_FLOAT_EQ(shiny.reflectivity, 0.4f);  // the floor setting comes after the overrides, by name
  EXPECT_EQ(shiny.diffuse, vec3(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(scene.materials[scene.meshes[placed.mesh].material].diffuse, vec3(1.0f));  // not overridden

  const Mesh& wave = scene.meshes[scene.instances[2].mesh];
  EXPECT_TRUE(wave.deformable);
  ASSERT_TRUE(wave.deform.has_value());
  EXPECT_EQ(wave.deform->displace_axis, 0);
  EXPECT_EQ(wave.deform->wave_axis, 1);
  EXPECT_FLOAT_EQ(wave.deform->amplitude, 0.5f);
  EXPECT_EQ(scene.deformable_meshes(), std::vector<std::uint32_t>{scene.instances[2].mesh});
  for (const Material& material : scene.materials) EXPECT_FLOAT_EQ(material.reflectivity, 0.4f);
}

TEST(SceneJson, LoadsEachFileOnceAndSharesStaticMeshesButNotDeformableOnes) {
  TempFolder folder;
  folder.write("tri.gltf", triangle_gltf("stone"));
  ScopedLogCapture log;  // each load of tri.gltf warns once about its degenerate triangle
  const Scene scene = load_scene_json_text(R"({"meshes": [
      { "file": "tri.gltf", "transform": { "translate": [1, 0, 0] } },
      { "file": "tri.gltf", "transform": { "translate": [2, 0, 0] } },
      { "file": "./tri.gltf", "deform": { "type": "sine" } },
      { "file": "tri.gltf", "deform": { "type": "sine" } }]})",
                                           folder.path() / "s.scene.json");
  EXPECT_EQ(log.count_warnings("degenerate"), 1);
  ASSERT_EQ(scene.instances.size(), 4u);
  // The two static entries share one mesh; each deformable entry has its own copy.
  EXPECT_EQ(scene.instances[0].mesh, scene.instances[1].mesh);
  EXPECT_EQ(scene.meshes.size(), 3u);
  EXPECT_NE(scene.instances[2].mesh, scene.instances[3].mesh);
  EXPECT_NE(scene.instances[2].mesh, scene.instances[0].mesh);
  EXPECT_EQ(scene.deformable_meshes().size(), 2u);
  EXPECT_FALSE(scene.meshes[scene.instances[0].mesh].deformable);
  EXPECT_FLOAT_EQ(scene.instances[1].transform[3].x, 2.0f);
}

TEST(SceneJson, LightCameraFramesAndDefaultWalkthrough) {
  TempFolder folder;
  folder.write("tri.gltf", triangle_gltf("m"));
  const Scene plain = load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}]})", folder.path() / "a.scene.json");
  EXPECT_EQ(plain.walkthrough.frame_count, 4900);
  EXPECT_GE(plain.walkthrough.camera.points.size(), 2u);  // assign_default_walkthrough's circle
  EXPECT_FALSE(plain.walkthrough.light.points.empty());

  const Scene lit = load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}], "frames": 100, "fps": 60,
      "light": {"color": [1, 0.5, 0.25], "intensity": 7, "range": 3, "path": [[0, 4, 0], [8, 4, 0]], "period_frames": 50},
      "camera": {"path": [[0, 1, 9], [1, 1, 9]], "fov_y_degrees": 40}, "sky_color": [0.1, 0.2, 0.3]})",
                                         folder.path() / "b.scene.json");
  EXPECT_EQ(lit.walkthrough.frame_count, 100);
  EXPECT_FLOAT_EQ(lit.walkthrough.frames_per_second, 60.0f);
  EXPECT_EQ(lit.light.color, vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(lit.light.intensity, 7.0f);
  EXPECT_FLOAT_EQ(lit.light.range, 3.0f);
  EXPECT_EQ(lit.light.position, vec3(0.0f, 4.0f, 0.0f));  // the path's first point
  EXPECT_EQ(lit.walkthrough.light.points.size(), 2u);
  EXPECT_EQ(lit.walkthrough.light.period_frames, 50);
  EXPECT_EQ(lit.walkthrough.camera.points, (std::vector<vec3>{vec3(0, 1, 9), vec3(1, 1, 9)}));
  EXPECT_TRUE(lit.walkthrough.camera.targets.empty());
  EXPECT_FLOAT_EQ(lit.walkthrough.camera.fov_y_degrees, 40.0f);
  EXPECT_EQ(lit.sky_color, vec3(0.1f, 0.2f, 0.3f));

  const Scene fixed = load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}], "light": {"position": [1, 2, 3]}})",
                                           folder.path() / "c.scene.json");
  EXPECT_EQ(fixed.walkthrough.light.points, std::vector<vec3>{vec3(1, 2, 3)});
  EXPECT_GE(fixed.walkthrough.camera.points.size(), 2u);  // no camera block: the default camera
}

// "reflection_fade" gives the reflections' distance fade in world units (docs/scene-format.md);
// without it the renderer fits one to the scene's size (render/scene_reflection_fade.h).
TEST(SceneJson, ReflectionFadeIsTakenAsGivenAndChecked) {
  TempFolder folder;
  folder.write("tri.gltf", triangle_gltf("m"));
  const std::filesystem::path origin = folder.path() / "fade.scene.json";
  const Scene plain = load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}]})", origin);
  EXPECT_FALSE(plain.reflection_fade.has_value());
  const Scene faded =
      load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}], "reflection_fade": {"start": 150, "end": 300.5}})", origin);
  ASSERT_TRUE(faded.reflection_fade.has_value());
  EXPECT_EQ(faded.reflection_fade->start, 150.0f);
  EXPECT_EQ(faded.reflection_fade->end, 300.5f);
  const Scene off =
      load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}], "reflection_fade": {"start": 0, "end": 0}})", origin);
  ASSERT_TRUE(off.reflection_fade.has_value());
  EXPECT_EQ(off.reflection_fade->end, 0.0f);

  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "reflection_fade": {"start": 30, "end": 15}})")
                .find("scene.json: /reflection_fade: the fade needs 0 <= start < end (or both 0: no fade), got start 30 "
                      "and end 15"),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "reflection_fade": {"start": 1}})")
                .find("/reflection_fade: missing required key \"end\""),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "reflection_fade": {"begin": 1, "end": 2}})")
                .find("/reflection_fade/begin: unknown key"),
            std::string::npos);
}

TEST(SceneJson, BuildErrorsNameTheFileAndJsonPath) {
  TempFolder folder;
  folder.write("tri.gltf", triangle_gltf("stone"));
  const std::filesystem::path origin = folder.path() / "bad.scene.json";

  const std::string missing = error_of([&] {
    load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}, {"file": "gone.glb"}]})", origin);
  });
  EXPECT_NE(missing.find(origin.string() + ": /meshes/1/file: no such mesh file \"gone.glb\""), std::string::npos)
      << missing;

  const std::string floor = error_of([&] {
    load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}], "floor": {"materials": ["stone", "marble"], "reflectivity": 1}})",
                         origin);
  });
  EXPECT_NE(floor.find("bad.scene.json: /floor/materials/1: no material named \"marble\" in the scene (its materials: stone)"),
            std::string::npos)
      << floor;

  // An error inside the mesh file keeps the glTF loader's message behind the JSON path.
  GltfBuilder broken;
  broken.add_mesh_node({{"attributes", {{"POSITION", broken.add_vec3(testing::unit_triangle())}}},
                        {"indices", broken.add_indices_u16({0, 1, 5})}});
  folder.write("broken.gltf", broken.gltf_text());
  const std::string inner = error_of([&] {
    load_scene_json_text(R"({"meshes": [{"file": "tri.gltf"}, {"file": "broken.gltf"}]})", origin);
  });
  EXPECT_NE(inner.find("bad.scene.json: /meshes/1/file: "), std::string::npos) << inner;
  EXPECT_NE(inner.find("broken.gltf: meshes[0].primitives[0]: index 5 out of range (3 vertices)"), std::string::npos)
      << inner;

  // A typo is reported before any mesh file is read (gone.glb would fail first otherwise).
  const std::string typo = error_of([&] {
    load_scene_json_text(R"({"meshes": [{"file": "gone.glb"}], "light": {"colour": [1, 1, 1]}})", origin);
  });
  EXPECT_NE(typo.find("/light/colour: unknown key"), std::string::npos) << typo;
}

TEST(SceneJson, LoadsFromAFileAndThroughLoadScene) {
  TempFolder folder;
  folder.write("tri.gltf", triangle_gltf("m"));
  const std::filesystem::path file = folder.write("room.scene.json", R"({"meshes": [{"file": "tri.gltf"}]})");
  EXPECT_EQ(load_scene_json(file).triangle_count(), 1u);
  EXPECT_EQ(load_scene(file.string()).name, "room");
  EXPECT_NE(error_of([&] { load_scene_json(folder.path() / "none.scene.json"); }).find("none.scene.json"),
            std::string::npos);
}

// ---- assets folder ----

TEST(SceneJsonAssets, FindAssetsDirPrefersOptionThenEnvironmentThenSceneEntry) {
  TempFolder folder;
  for (const char* name : {"option", "env", "scene"}) std::filesystem::create_directories(folder.path() / name);
  LoadOptions options;
  options.assets_dir = folder.path() / "option";
  const std::filesystem::path scene_entry = folder.path() / "scene";
  {
    ScopedEnv env("GLINT_ASSETS", (folder.path() / "env").string());
    EXPECT_EQ(find_assets_dir(options, scene_entry), folder.path() / "option");
    EXPECT_EQ(find_assets_dir({}, scene_entry), folder.path() / "env");
  }
  {
    ScopedEnv env("GLINT_ASSETS", std::nullopt);
    EXPECT_EQ(find_assets_dir({}, scene_entry), folder.path() / "scene");
  }
}

TEST(SceneJsonAssets, ANamedFolderThatDoesNotExistIsAnErrorSayingWhereItWasGiven) {
  // Before, each was skipped and glint went on to the next candidate, down to ../shared/assets.
  TempFolder folder;
  for (const char* name : {"env", "scene"}) std::filesystem::create_directories(folder.path() / name);
  LoadOptions options;
  options.assets_dir = folder.path() / "option-missing";
  {
    ScopedEnv env("GLINT_ASSETS", (folder.path() / "env").string());
    const std::string message = error_of([&] { find_assets_dir(options, folder.path() / "scene"); });
    EXPECT_NE(message.find("option-missing', given by the assets option (--assets), is not a folder"), std::string::npos)
        << message;
  }
  {
    ScopedEnv env("GLINT_ASSETS", (folder.path() / "env-missing").string());
    const std::string message = error_of([&] { find_assets_dir({}, folder.path() / "scene"); });
    EXPECT_NE(message.find("env-missing', given by $GLINT_ASSETS, is not a folder"), std::string::npos) << message;
  }
  ScopedEnv env("GLINT_ASSETS", std::nullopt);
  const std::string message = error_of([&] { find_assets_dir({}, folder.path() / "scene-missing"); });
  EXPECT_NE(message.find("scene-missing', given by the scene's \"assets\" entry, is not a folder"), std::string::npos)
      << message;
  // Through a scene file: the error names the file and its /assets entry.
  const std::string scene = R"({"assets": "no-such-folder", "meshes": [{"file": "m.gltf"}]})";
  const std::string loaded = error_of([&] { load_scene_json_text(scene, folder.path() / "x.scene.json"); });
  EXPECT_NE(loaded.find("x.scene.json: /assets: assets folder not found: '"), std::string::npos) << loaded;
  EXPECT_NE(loaded.find("no-such-folder', given by the scene's \"assets\" entry"), std::string::npos) << loaded;
}

TEST(SceneJsonAssets, FindAssetsDirListsEveryPlaceItLookedWhenNoneExists) {
  TempFolder folder;
  // The fallbacks relative to the current directory and the executable must not exist for this test.
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::create_directories(folder.path() / "cwd");
  std::filesystem::current_path(folder.path() / "cwd");
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe").parent_path();
  if (std::filesystem::exists(exe / ".." / "shared" / "assets") || std::filesystem::exists(exe / ".." / ".." / "shared" / "assets")) {
    std::filesystem::current_path(previous);
    GTEST_SKIP() << "a shared/assets folder exists beside the test executable";
  }
  ScopedEnv env("GLINT_ASSETS", std::nullopt);
  const std::string message = error_of([&] { find_assets_dir({}, std::nullopt); });
  std::filesystem::current_path(previous);
  EXPECT_EQ(message.find('\n'), std::string::npos);  // one line
  for (const std::string part : {"assets folder not found", "shared/assets (from the current directory)", "executable",
                                 "GLINT_ASSETS"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
}

TEST(SceneJsonAssets, MeshPathsResolveAgainstAssetsWhenGivenElseTheSceneFolder) {
  TempFolder folder;
  folder.write("scenes/local.gltf", triangle_gltf("local"));
  folder.write("assets/shared.gltf", triangle_gltf("shared"));
  folder.write("override/shared.gltf", triangle_gltf("override"));
  const std::filesystem::path origin = folder.path() / "scenes" / "x.scene.json";
  ScopedEnv env("GLINT_ASSETS", std::nullopt);

  const Scene local = load_scene_json_text(R"({"meshes": [{"file": "local.gltf"}]})", origin);
  EXPECT_EQ(local.materials[0].name, "local");
  const std::string with_assets = R"({"assets": "../assets", "meshes": [{"file": "shared.gltf"}]})";
  EXPECT_EQ(load_scene_json_text(with_assets, origin).materials[0].name, "shared");

  LoadOptions options;
  options.assets_dir = folder.path() / "override";
  EXPECT_EQ(load_scene_json_text(with_assets, origin, options).materials[0].name, "override");
  {
    ScopedEnv override_env("GLINT_ASSETS", (folder.path() / "override").string());
    EXPECT_EQ(load_scene_json_text(with_assets, origin).materials[0].name, "override");
    // A scene without "assets" keeps its own folder whatever the environment says.
    EXPECT_EQ(load_scene_json_text(R"({"meshes": [{"file": "local.gltf"}]})", origin).materials[0].name, "local");
  }
  const SceneDescription description = parse_scene_description(with_assets, origin);
  EXPECT_EQ(resolve_mesh_path(description, description.meshes[0]), (folder.path() / "assets" / "shared.gltf").lexically_normal());
}

TEST(SceneJsonAppend, ReindexesTexturesMaterialsAndMeshesAndComposesTransforms) {
  Scene into;
  into.textures.resize(2);
  into.materials.resize(3);
  into.meshes.resize(1);
  Scene part;
  part.textures.resize(1);
  part.materials.resize(1);
  part.materials[0].diffuse_texture = 0;
  part.meshes.resize(2);
  part.meshes[0].name = "a";
  part.meshes[1].material = 0;
  part.instances.push_back({"i", 1, glm::translate(mat4(1.0f), vec3(0, 1, 0))});
  const AppendedPart where = append_scene(into, part, glm::scale(mat4(1.0f), vec3(2.0f)), "p");
  EXPECT_EQ(where.first_mesh, 1u);
  EXPECT_EQ(where.first_material, 3u);
  EXPECT_EQ(into.textures.size(), 3u);
  EXPECT_EQ(into.materials[3].diffuse_texture, 2);
  EXPECT_EQ(into.meshes[2].material, 3u);
  EXPECT_EQ(into.meshes[1].name, "p/a");
  ASSERT_EQ(into.instances.size(), 1u);
  EXPECT_EQ(into.instances[0].mesh, 2u);
  EXPECT_EQ(into.instances[0].name, "p/i");
  // The part's own translation happens first, then the appended scale: (0, 1, 0) -> (0, 2, 0).
  expect_near(apply(into.instances[0].transform, vec3(0.0f)), vec3(0.0f, 2.0f, 0.0f));
  append_instances(into, part, where, mat4(1.0f), "q");
  EXPECT_EQ(into.meshes.size(), 3u);
  EXPECT_EQ(into.instances[1].mesh, 2u);
}

// ---- the example scene file ----

TEST(SceneJsonExample, SponzaSceneFileParsesIntoTheExpectedDescription) {
  const std::filesystem::path file = testing::source_dir() / "scenes" / "sponza.scene.json";
  std::ifstream in(file);
  ASSERT_TRUE(in) << file;
  std::stringstream text;
  text << in.rdbuf();
  const SceneDescription description = parse_scene_description(text.str(), file);
  EXPECT_EQ(description.name, "sponza");
  EXPECT_EQ(description.assets, std::filesystem::path("../../shared/assets"));
  ASSERT_EQ(description.meshes.size(), 7u);  // the atrium and 6 creatures
  EXPECT_EQ(description.meshes[0].file, std::filesystem::path("sponza_dabrovic/sponza.obj"));
  int armadillos = 0, deformable = 0;
  for (const MeshEntry& entry : description.meshes) {
    if (entry.file.string().find("armadillo") != std::string::npos) ++armadillos;
    if (entry.deform) ++deformable;
  }
  EXPECT_EQ(armadillos, 4);
  EXPECT_EQ(deformable, 2);
  EXPECT_EQ(description.frames, 4900);
  ASSERT_TRUE(description.floor.has_value());
  EXPECT_EQ(description.floor->materials, std::vector<std::string>{"sp_00_pod"});
  EXPECT_GT(description.floor->reflectivity, 0.0f);
  ASSERT_TRUE(description.camera.has_value());
  EXPECT_EQ(description.camera->points.size(), description.camera->targets.size());
  // The camera visits all three halls: the south aisle (z > 4), the corridor (|z| < 2), the north aisle (z < -4).
  bool south = false, corridor = false, north = false;
  for (const vec3& p : description.camera->points) {
    EXPECT_TRUE(p.x > -17.4f && p.x < 17.4f && p.z > -7.8f && p.z < 7.8f && p.y > 0.1f && p.y < 4.0f) << p.x << " " << p.z;
    south = south || p.z > 4.0f;
    corridor = corridor || std::abs(p.z) < 2.0f;
    north = north || p.z < -4.0f;
  }
  EXPECT_TRUE(south && corridor && north);
  ASSERT_TRUE(description.light.has_value());
  ASSERT_EQ(description.light->path.size(), 2u);
  EXPECT_EQ(description.light->path[0].y, description.light->path[1].y);  // a fixed height
  // Every creature stands inside the building, in the corridor (|z| < 2).
  for (std::size_t i = 1; i < description.meshes.size(); ++i) {
    const vec3 at = description.meshes[i].transform.translate;
    EXPECT_LT(std::abs(at.x), 16.0f);
  }
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST(SceneJsonExample, TheDocumentationsCompleteExampleParses) {
  const std::filesystem::path doc = testing::source_dir() / "docs" / "scene-format.md";
  std::ifstream in(doc);
  ASSERT_TRUE(in) << doc;
  std::stringstream text;
  text << in.rdbuf();
  const std::string markdown = text.str();
  const std::size_t start = markdown.find("```json\n");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = markdown.find("```", start + 8);
  ASSERT_NE(end, std::string::npos);
  const SceneDescription description =
      parse_scene_description(markdown.substr(start + 8, end - start - 8), "gallery.scene.json");
  EXPECT_EQ(description.name, "gallery");
  EXPECT_EQ(description.meshes.size(), 3u);
  EXPECT_TRUE(description.meshes[2].deform.has_value());
  EXPECT_TRUE(description.meshes[1].material.reflectivity.has_value());
  EXPECT_EQ(description.frames, 600);
}

}  // namespace
}  // namespace glint
