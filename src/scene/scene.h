#pragma once
// The scene model: what every loader produces and every later stage (animation, acceleration
// structures, rendering) consumes. Plain data plus a few queries; no file formats, no GL.
//
// Conventions: right-handed, y up, metres-ish units; triangles are counter-clockwise when seen from
// their front side; one material per mesh (loaders split objects by material); texture rows are
// stored top row first and v = 0 is the bottom of the image (OBJ/GL convention), so texel row =
// (1 - v) * height.
#include "core/math.h"
#include "scene/walkthrough.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glint {

struct Texture {
  std::string name;                 // file path as resolved, or "procedural:<kind>"
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;   // width * height * 4 bytes, sRGB-encoded colour, top row first
  bool placeholder = false;         // true when the file was missing and a checker stands in
};

struct Material {
  std::string name = "default";
  vec3 diffuse{0.8f};               // linear RGB, multiplied with the texture
  int diffuse_texture = -1;         // index into Scene::textures, -1 for none
  vec3 specular{0.04f};
  float specular_exponent = 32.0f;  // Blinn-Phong
  float reflectivity = 0.0f;        // 0..1: weight of the mirror reflection in the final colour
  float roughness = 0.0f;           // spare channel for glossy reflections later
  vec3 emissive{0.0f};
};

// The paper's "sine wave algorithm": every vertex moves along `displace_axis` by
// amplitude * sin(frequency * rest[wave_axis] + speed * t), in the mesh's own (object) space.
struct SineDeform {
  int displace_axis = 1;            // 0 = x, 1 = y, 2 = z
  int wave_axis = 0;
  float amplitude = 0.05f;
  float frequency = 4.0f;           // radians per unit of the rest coordinate
  float speed = 2.0f;               // radians per second
};

struct Mesh {
  std::string name;
  std::vector<vec3> positions;
  std::vector<vec3> normals;        // one per position, unit length
  std::vector<vec2> uvs;            // one per position, or empty when the mesh has no UVs
  std::vector<std::uint32_t> indices;  // three per triangle
  std::uint32_t material = 0;       // index into Scene::materials
  bool deformable = false;          // its vertices change every frame
  std::optional<SineDeform> deform; // how, when deformable

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
  Aabb bounds() const;              // object space
};

struct Instance {
  std::string name;
  std::uint32_t mesh = 0;           // index into Scene::meshes
  mat4 transform{1.0f};             // object to world
};

struct PointLight {
  vec3 position{0.0f, 5.0f, 0.0f};  // rest position; the walkthrough's light path moves it
  vec3 color{1.0f};
  float intensity = 20.0f;          // radiant intensity (docs/render.md); attenuation is 1 / (1 + (d / range)^2)
  float range = 10.0f;
};

// Distance fade of reflections (docs/ssr.md): a reflection found farther than `start` fades out
// smoothly by `end`, in world units; end <= 0 turns the fade off.
struct DistanceFade {
  float start = 0.0f;
  float end = 0.0f;
};

struct Scene {
  std::string name;                 // preset name or file stem
  std::string source;               // file path, or "built-in"
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Instance> instances;
  PointLight light;
  Walkthrough walkthrough;
  vec3 sky_color{0.55f, 0.65f, 0.8f};  // colour of rays that leave the scene
  // A scene file's "reflection_fade". Without it the renderer fits the fade to the scene's size
  // (render/scene_reflection_fade.h).
  std::optional<DistanceFade> reflection_fade;

  // Totals over instances (a mesh drawn twice counts twice), as the paper counts its scene.
  std::size_t vertex_count() const;
  std::size_t triangle_count() const;
  Aabb world_bounds() const;
  std::vector<std::uint32_t> deformable_meshes() const;

  // Throws glint::Error (naming `source`) if the scene is empty, an index is out of range, or a
  // position/normal is not finite. Loaders call this before returning.
  void validate() const;
};

}  // namespace glint
