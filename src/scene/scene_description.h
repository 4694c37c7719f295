#pragma once
// A scene file (*.scene.json, docs/scene-format.md) after parsing and checking, before any mesh file is
// read. Parsing (scene_json_parser.h) and building (scene_json_builder.h) are separate steps so that a
// typo anywhere in the file is reported before megabytes of meshes are loaded.
#include "core/math.h"
#include "scene/scene.h"
#include "scene/walkthrough.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glint {

// "material" of a mesh entry: values that replace those of every material of the entry's file.
struct MaterialOverrides {
  std::optional<vec3> diffuse;
  std::optional<vec3> specular;
  std::optional<float> specular_exponent;
  std::optional<float> reflectivity;
  std::optional<float> roughness;
  std::optional<vec3> emissive;

  bool operator==(const MaterialOverrides&) const = default;
  void apply(Material& material) const;
};

// "transform" of a mesh entry. The matrix scales first, then rotates about X, then Y, then Z (degrees),
// then translates: M = T * Rz * Ry * Rx * S.
struct MeshTransformSpec {
  vec3 translate{0.0f};
  vec3 rotate_degrees{0.0f};
  vec3 scale{1.0f};

  mat4 matrix() const;
};

struct MeshEntry {
  std::string json_pointer;           // "/meshes/2": where the entry is, for errors found while building
  std::filesystem::path file;         // as written in the file
  std::string name;                   // "name", else the file's stem
  MeshTransformSpec transform;
  MaterialOverrides material;
  std::optional<SineDeform> deform;   // set: the entry's meshes are deformable
};

struct LightDescription {
  vec3 color{1.0f};
  float intensity = 60.0f;
  float range = 10.0f;
  std::optional<vec3> position;       // rest position; default: the first path point
  std::vector<vec3> path;             // empty: a fixed light at `position`
  int period_frames = 980;
};

struct FloorDescription {
  std::string json_pointer;           // "/floor"
  std::vector<std::string> materials; // material names as the mesh files call them
  float reflectivity = 0.5f;
};

struct SceneDescription {
  std::filesystem::path origin;       // the scene file; names it in errors, base of relative paths
  std::string name;                   // "name", else the file name without ".scene.json"
  std::optional<std::filesystem::path> assets;  // as written; relative to the scene file's folder
  std::vector<MeshEntry> meshes;
  std::optional<LightDescription> light;
  std::optional<CameraPathSpec> camera;
  int frames = 4900;
  float frames_per_second = 30.0f;
  std::optional<vec3> sky_color;
  std::optional<FloorDescription> floor;
  std::optional<DistanceFade> reflection_fade;  // "reflection_fade", world units
};

}  // namespace glint
