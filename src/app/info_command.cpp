#include "app/info_command.h"

#include "scene/load_scene.h"

#include <fmt/format.h>

namespace glint {

void add_info_command(CLI::App& app, InfoOptions& options) {
  CLI::App* info = app.add_subcommand("info", "Describe a scene: meshes, counts, deformables, bounds, materials, light, paths");
  info->add_option("scene", options.scene, "Preset (atrium, atrium-simple, sponza) or file (.obj, .gltf, .glb, .scene.json)")
      ->capture_default_str();
  info->add_flag("--json", options.json, "Print JSON instead of text");
  info->add_flag("--flat-normals", options.flat_normals, "Compute flat instead of smooth normals where a mesh has none");
}

int run_info_command(const InfoOptions& options) {
  LoadOptions load;
  load.flat_normals = options.flat_normals;
  const Scene scene = load_scene(options.scene, load);
  fmt::print("scene      {} ({})\n", scene.name, scene.source);
  fmt::print("meshes     {}  instances {}\n", scene.meshes.size(), scene.instances.size());
  fmt::print("vertices   {}\ntriangles  {}\n", scene.vertex_count(), scene.triangle_count());
  return 0;
}

}  // namespace glint
