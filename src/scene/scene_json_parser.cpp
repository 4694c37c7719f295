#include "scene/scene_json_parser.h"

#include "core/untrusted_text.h"
#include "scene/json_field.h"

#include <algorithm>
#include <cctype>
#include <limits>

namespace glint {
namespace {

constexpr float kHuge = std::numeric_limits<float>::max();
constexpr std::size_t kMaxPathBytes = 4096;  // Linux's PATH_MAX

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

// "axis": "x" | "y" | "z" -> 0 | 1 | 2.
int parse_axis(const JsonField& field) {
  const std::string name = field.string();
  if (name == "x") return 0;
  if (name == "y") return 1;
  if (name == "z") return 2;
  field.error("unknown axis \"{}\" (expected \"x\", \"y\" or \"z\")", untrusted_text(name));
}

vec3 parse_color(const JsonField& field) {
  const vec3 color = field.vec3_value();
  if (color.x < 0.0f || color.y < 0.0f || color.z < 0.0f) field.error("colour components must be >= 0");
  return color;
}

MeshTransformSpec parse_transform(const JsonField& field) {
  field.require_object({"translate", "rotate", "scale"});
  MeshTransformSpec spec;
  if (auto f = field.find("translate")) spec.translate = f->vec3_value();
  if (auto f = field.find("rotate")) spec.rotate_degrees = f->vec3_value();
  if (auto f = field.find("scale")) {
    if (f->json().is_number()) spec.scale = vec3(f->number());
    else if (f->json().is_array()) spec.scale = f->vec3_value();
    else f->error("expected a number or [x, y, z], got {}", json_type_name(f->json()));
    // A zero scale flattens the mesh into degenerate triangles; a negative one is a legal mirror.
    if (spec.scale.x == 0.0f || spec.scale.y == 0.0f || spec.scale.z == 0.0f) f->error("scale must not be 0");
  }
  return spec;
}

MaterialOverrides parse_material_overrides(const JsonField& field) {
  field.require_object({"diffuse", "specular", "specular_exponent", "reflectivity", "roughness", "emissive"});
  MaterialOverrides overrides;
  if (auto f = field.find("diffuse")) overrides.diffuse = parse_color(*f);
  if (auto f = field.find("specular")) overrides.specular = parse_color(*f);
  if (auto f = field.find("specular_exponent")) overrides.specular_exponent = f->number_in(1.0f, 1.0e5f);
  if (auto f = field.find("reflectivity")) overrides.reflectivity = f->number_in(0.0f, 1.0f);
  if (auto f = field.find("roughness")) overrides.roughness = f->number_in(0.0f, 1.0f);
  if (auto f = field.find("emissive")) overrides.emissive = parse_color(*f);
  return overrides;
}

SineDeform parse_deform(const JsonField& field) {
  field.require_object({"type", "axis", "along", "amplitude", "frequency", "speed"});
  const JsonField type = field.at("type");
  if (type.string() != "sine") type.error("unknown deformer \"{}\" (expected \"sine\")", untrusted_text(type.string()));
  SineDeform deform;
  if (auto f = field.find("axis")) deform.displace_axis = parse_axis(*f);
  if (auto f = field.find("along")) deform.wave_axis = parse_axis(*f);
  if (auto f = field.find("amplitude")) deform.amplitude = f->number();
  if (auto f = field.find("frequency")) deform.frequency = f->number();
  if (auto f = field.find("speed")) deform.speed = f->number();
  return deform;
}

MeshEntry parse_mesh_entry(const JsonField& field) {
  field.require_object({"file", "name", "transform", "material", "deform"});
  MeshEntry entry;
  entry.json_pointer = field.pointer();
  const JsonField file = field.at("file");
  const std::string file_text = file.string();
  if (file_text.empty()) file.error("empty file name");
  // The path reaches every message of the mesh's loader; one that no file system could open, or with
  // control characters, is a mistake (or an attack on the terminal) caught here, shown escaped.
  if (file_text.size() > kMaxPathBytes)
    file.error("the file name is {} bytes long (at most {}): \"{}\"", file_text.size(), kMaxPathBytes,
               untrusted_text(file_text));
  if (std::ranges::any_of(file_text, [](unsigned char c) { return c < 0x20 || c == 0x7F; }))
    file.error("the file name \"{}\" contains control characters", untrusted_text(file_text));
  // Checked here, not when loading, so that the whole file is vetted before any mesh is read.
  const std::string lower = lowercase(file_text);
  if (!ends_with(lower, ".obj") && !ends_with(lower, ".gltf") && !ends_with(lower, ".glb"))
    file.error("unsupported mesh file \"{}\" (expected .obj, .gltf or .glb)", untrusted_text(file_text));
  entry.file = file_text;
  entry.name = std::filesystem::path(file_text).stem().string();
  if (auto f = field.find("name")) {
    entry.name = f->string();
    if (entry.name.empty()) f->error("empty name");
  }
  if (auto f = field.find("transform")) entry.transform = parse_transform(*f);
  if (auto f = field.find("material")) entry.material = parse_material_overrides(*f);
  if (auto f = field.find("deform")) entry.deform = parse_deform(*f);
  return entry;
}

LightDescription parse_light(const JsonField& field) {
  field.require_object({"color", "intensity", "range", "position", "path", "period_frames"});
  LightDescription light;
  if (auto f = field.find("color")) light.color = parse_color(*f);
  if (auto f = field.find("intensity")) light.intensity = f->number_in(0.0f, kHuge);
  if (auto f = field.find("range")) {
    light.range = f->number();
    if (light.range <= 0.0f) f->error("range must be > 0");
  }
  if (auto f = field.find("position")) light.position = f->vec3_value();
  if (auto f = field.find("path")) {
    light.path = f->points();
    if (light.path.empty()) f->error("the light path needs at least one point");
  }
  if (!light.position && light.path.empty()) field.error("the light needs a \"position\" or a \"path\"");
  if (auto f = field.find("period_frames")) {
    light.period_frames = f->integer();
    if (light.period_frames <= 0) f->error("period_frames must be > 0");
  }
  return light;
}

CameraPathSpec parse_camera(const JsonField& field) {
  field.require_object({"path", "targets", "position", "target", "fov_y_degrees"});
  CameraPathSpec camera;
  if (auto f = field.find("fov_y_degrees")) camera.fov_y_degrees = f->number_in(1.0f, 179.0f);
  // A fixed camera ("position" + "target") or a path ("path", optional "targets"), not both.
  const auto position = field.find("position");
  const auto target = field.find("target");
  if (position || target) {
    if (auto f = field.find("path")) f->error("give either \"path\" (a moving camera) or \"position\" and \"target\" (a fixed one), not both");
    if (auto f = field.find("targets")) f->error("\"targets\" belongs to a \"path\"; a fixed camera has one \"target\"");
    if (!position) field.error("a fixed camera needs \"position\" as well as \"target\"");
    if (!target) field.error("a fixed camera needs \"target\" as well as \"position\"");
    camera = CameraPathSpec::fixed(position->vec3_value(), target->vec3_value(), camera.fov_y_degrees);
    if (glm::length(camera.targets.front() - camera.points.front()) <= 0.0f) target->error("the target equals the position");
    return camera;
  }
  const JsonField path = field.at("path");
  camera.points = path.points();
  if (camera.points.size() < 2)
    path.error("the camera path needs at least 2 points, got {} (a camera that does not move: \"position\" and "
               "\"target\")",
               camera.points.size());
  // The spline needs two distinct points; said here with the JSON path rather than by the spline.
  // (Targets may all be one point: the moving camera keeps looking at it.)
  if (std::all_of(camera.points.begin(), camera.points.end(), [&](const vec3& p) { return p == camera.points.front(); }))
    path.error("the camera path's {} points are all the same point (a camera that does not move: \"position\" and "
               "\"target\")",
               camera.points.size());
  if (auto f = field.find("targets")) {
    camera.targets = f->points();
    if (camera.targets.size() < 2) f->error("camera targets need at least 2 points, got {}", camera.targets.size());
  }
  return camera;
}

FloorDescription parse_floor(const JsonField& field) {
  field.require_object({"materials", "reflectivity"});
  FloorDescription floor;
  floor.json_pointer = field.pointer();
  const JsonField materials = field.at("materials");
  for (const JsonField& name : materials.elements()) floor.materials.push_back(name.string());
  if (floor.materials.empty()) materials.error("expected at least one material name");
  floor.reflectivity = field.at("reflectivity").number_in(0.0f, 1.0f);
  return floor;
}

// {"start": s, "end": e} in world units, 0 <= s < e; or {"start": 0, "end": 0}: no fade.
DistanceFade parse_reflection_fade(const JsonField& field) {
  field.require_object({"start", "end"});
  DistanceFade fade;
  fade.start = field.at("start").number();
  fade.end = field.at("end").number();
  const bool off = fade.start == 0.0f && fade.end == 0.0f;
  if (!off && !(fade.start >= 0.0f && fade.start < fade.end))
    field.error("the fade needs 0 <= start < end (or both 0: no fade), got start {} and end {}", fade.start, fade.end);
  return fade;
}

// "sponza.scene.json" -> "sponza"; "x.json" -> "x".
std::string scene_name_from(const std::filesystem::path& origin) {
  std::string name = origin.filename().string();
  for (std::string_view suffix : {".scene.json", ".json"})
    if (ends_with(lowercase(name), suffix)) return name.substr(0, name.size() - suffix.size());
  return name;
}

}  // namespace

SceneDescription parse_scene_description(std::string_view text, const std::filesystem::path& origin) {
  const std::string label = origin.string();
  const nlohmann::json document = parse_json_text(text, label);
  const JsonField root(document, label, "");
  root.require_object(
      {"name", "assets", "meshes", "light", "camera", "frames", "fps", "sky_color", "floor", "reflection_fade"});

  SceneDescription description;
  description.origin = origin;
  description.name = scene_name_from(origin);
  if (auto f = root.find("name")) description.name = f->string();
  if (auto f = root.find("assets")) {
    const std::string assets = f->string();
    if (assets.empty()) f->error("empty folder name");
    description.assets = assets;
  }
  const JsonField meshes = root.at("meshes");
  for (const JsonField& entry : meshes.elements()) description.meshes.push_back(parse_mesh_entry(entry));
  if (description.meshes.empty()) meshes.error("the scene has no meshes (expected at least one entry)");
  if (auto f = root.find("light")) description.light = parse_light(*f);
  if (auto f = root.find("camera")) description.camera = parse_camera(*f);
  if (auto f = root.find("frames")) {
    description.frames = f->integer();
    if (description.frames <= 0) f->error("frames must be > 0, got {}", description.frames);
  }
  if (auto f = root.find("fps")) {
    description.frames_per_second = f->number();
    if (description.frames_per_second <= 0.0f) f->error("fps must be > 0");
  }
  if (auto f = root.find("sky_color")) description.sky_color = parse_color(*f);
  if (auto f = root.find("floor")) description.floor = parse_floor(*f);
  if (auto f = root.find("reflection_fade")) description.reflection_fade = parse_reflection_fade(*f);
  return description;
}

}  // namespace glint
