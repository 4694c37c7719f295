#include "scene/scene_json_builder.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/append_scene.h"
#include "scene/assets_dir.h"
#include "scene/default_walkthrough.h"
#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"

#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <string>
#include <vector>

namespace glint {
namespace {

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

// The folder relative mesh paths start from (see resolve_mesh_path).
std::filesystem::path mesh_base_folder(const SceneDescription& description, const LoadOptions& options) {
  const std::filesystem::path scene_folder = description.origin.parent_path();
  if (!description.assets) return scene_folder;
  const std::filesystem::path written = *description.assets;
  const std::filesystem::path from_scene = written.is_absolute() ? written : scene_folder / written;
  try {
    return find_assets_dir(options, from_scene);
  } catch (const Error& e) {
    fail("{}: /assets: {}", description.origin.string(), e.what());
  }
}

Scene load_mesh_file(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string extension = lowercase(path.extension().string());
  if (extension == ".obj") return load_obj(path, options);
  return load_gltf(path, options);  // .gltf or .glb: the parser accepts nothing else
}

// One loaded file appended with one set of material overrides: later entries with the same file and
// the same overrides (and no deformer) share its meshes and materials instead of copying them.
struct SharedPart {
  std::string path;
  MaterialOverrides overrides;
  AppendedPart where;
};

void apply_floor(Scene& scene, const SceneDescription& description) {
  const FloorDescription& floor = *description.floor;
  for (std::size_t i = 0; i < floor.materials.size(); ++i) {
    bool found = false;
    for (Material& material : scene.materials)
      if (material.name == floor.materials[i]) {
        material.reflectivity = floor.reflectivity;
        found = true;
      }
    if (!found) {
      std::vector<std::string> names;
      for (const Material& material : scene.materials)
        if (std::find(names.begin(), names.end(), material.name) == names.end()) names.push_back(material.name);
      fail("{}: {}/materials/{}: no material named \"{}\" in the scene (its materials: {})",
           description.origin.string(), floor.json_pointer, i, floor.materials[i], fmt::join(names, ", "));
    }
  }
}

void apply_walkthrough(Scene& scene, const SceneDescription& description) {
  scene.walkthrough.frame_count = description.frames;  // first: a default light may follow the camera over all frames
  scene.walkthrough.frames_per_second = description.frames_per_second;
  // The default walkthrough is placed from the geometry, for the file's camera when it has one;
  // whatever the file gives replaces its part.
  if (!description.camera || !description.light) assign_default_walkthrough(scene, description.camera);
  if (description.camera) scene.walkthrough.camera = *description.camera;
  if (description.light) {
    const LightDescription& light = *description.light;
    scene.light.color = light.color;
    scene.light.intensity = light.intensity;
    scene.light.range = light.range;
    scene.light.position = light.position ? *light.position : light.path.front();
    scene.walkthrough.light.points = light.path.empty() ? std::vector<vec3>{scene.light.position} : light.path;
    scene.walkthrough.light.period_frames = light.period_frames;
  }
}

}  // namespace

std::filesystem::path resolve_mesh_path(const SceneDescription& description, const MeshEntry& entry,
                                        const LoadOptions& options) {
  if (entry.file.is_absolute()) return entry.file;
  return (mesh_base_folder(description, options) / entry.file).lexically_normal();
}

Scene build_scene(const SceneDescription& description, const LoadOptions& options) {
  const std::string label = description.origin.string();
  Scene scene;
  scene.name = description.name;
  scene.source = label;

  // Resolve and check every path first, so a missing file is reported before any file is loaded.
  std::vector<std::filesystem::path> paths;
  for (const MeshEntry& entry : description.meshes) {
    paths.push_back(resolve_mesh_path(description, entry, options));
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(paths.back(), ignored))
      fail("{}: {}/file: no such mesh file \"{}\" (looked for {})", label, entry.json_pointer, entry.file.string(),
           paths.back().string());
  }

  std::map<std::string, Scene> loaded;  // each file once, however many entries use it
  std::vector<SharedPart> shared;
  for (std::size_t i = 0; i < description.meshes.size(); ++i) {
    const MeshEntry& entry = description.meshes[i];
    const std::string key = paths[i].string();
    auto part = loaded.find(key);
    if (part == loaded.end()) {
      try {
        part = loaded.emplace(key, load_mesh_file(paths[i], options)).first;
      } catch (const Error& e) {
        fail("{}: {}/file: {}", label, entry.json_pointer, e.what());  // keep the loader's own message
      }
    }
    const mat4 transform = entry.transform.matrix();

    if (!entry.deform) {
      const auto same = std::find_if(shared.begin(), shared.end(), [&](const SharedPart& s) {
        return s.path == key && s.overrides == entry.material;
      });
      if (same != shared.end()) {
        append_instances(scene, part->second, same->where, transform, entry.name);
        continue;
      }
    }
    // A deformable entry always gets its own copies: its meshes move independently of other entries'.
    const AppendedPart where = append_scene(scene, part->second, transform, entry.name);
    for (std::uint32_t m = 0; m < where.material_count; ++m) entry.material.apply(scene.materials[where.first_material + m]);
    if (entry.deform) {
      for (std::uint32_t m = 0; m < where.mesh_count; ++m) {
        Mesh& mesh = scene.meshes[where.first_mesh + m];
        mesh.deformable = true;
        mesh.deform = *entry.deform;
      }
    } else {
      shared.push_back({key, entry.material, where});
    }
  }

  if (description.floor) apply_floor(scene, description);
  if (description.sky_color) scene.sky_color = *description.sky_color;
  scene.reflection_fade = description.reflection_fade;
  apply_walkthrough(scene, description);
  log_info("{}: {} meshes, {} instances, {} triangles", label, scene.meshes.size(), scene.instances.size(),
           scene.triangle_count());
  scene.validate();
  return scene;
}

}  // namespace glint
