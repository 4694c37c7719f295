#include "app/info_command.h"

#include "core/untrusted_text.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <string>

namespace glint {
namespace {

std::string vec_text(const vec3& v) { return fmt::format("({:.2f}, {:.2f}, {:.2f})", v.x, v.y, v.z); }
nlohmann::json vec_json(const vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

// Thousands separators make 618000 vs 61800 readable at a glance.
std::string count_text(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

nlohmann::json scene_json(const Scene& scene) {
  nlohmann::json j;
  j["name"] = untrusted_text(scene.name);
  j["source"] = scene.source;
  j["vertices"] = scene.vertex_count();
  j["triangles"] = scene.triangle_count();
  const Aabb bounds = scene.world_bounds();
  j["bounds"] = {{"min", vec_json(bounds.min)}, {"max", vec_json(bounds.max)}};
  for (const Mesh& mesh : scene.meshes) {
    nlohmann::json m = {{"name", untrusted_text(mesh.name)}, {"vertices", mesh.vertex_count()}, {"triangles", mesh.triangle_count()},
                        {"material", untrusted_text(scene.materials[mesh.material].name)}, {"deformable", mesh.deformable}};
    if (mesh.deform)
      m["deform"] = {{"type", "sine"}, {"axis", axis_name(mesh.deform->displace_axis)},
                     {"along", axis_name(mesh.deform->wave_axis)}, {"amplitude", mesh.deform->amplitude},
                     {"frequency", mesh.deform->frequency}, {"speed", mesh.deform->speed}};
    j["meshes"].push_back(m);
  }
  for (const Instance& instance : scene.instances)
    j["instances"].push_back({{"name", untrusted_text(instance.name)}, {"mesh", untrusted_text(scene.meshes[instance.mesh].name)}});
  for (const Material& material : scene.materials) {
    nlohmann::json m = {{"name", untrusted_text(material.name)}, {"diffuse", vec_json(material.diffuse)},
                        {"reflectivity", material.reflectivity}, {"specular_exponent", material.specular_exponent}};
    if (material.diffuse_texture >= 0) m["texture"] = untrusted_text(scene.textures[static_cast<std::size_t>(material.diffuse_texture)].name);
    j["materials"].push_back(m);
  }
  for (const Texture& texture : scene.textures)
    j["textures"].push_back({{"name", untrusted_text(texture.name)}, {"width", texture.width}, {"height", texture.height},
                             {"placeholder", texture.placeholder}});
  j["light"] = {{"position", vec_json(scene.light.position)}, {"color", vec_json(scene.light.color)},
                {"intensity", scene.light.intensity}, {"range", scene.light.range}};
  const WalkthroughAnimation animation(scene);
  j["walkthrough"] = {{"frames", scene.walkthrough.frame_count},
                      {"fps", scene.walkthrough.frames_per_second},
                      {"camera_points", scene.walkthrough.camera.points.size()},
                      {"camera_fixed", scene.walkthrough.camera.is_fixed()},
                      {"camera_path_length", animation.camera_path_length()},
                      {"light_points", scene.walkthrough.light.points.size()},
                      {"light_path_length", animation.light_path_length()},
                      {"light_period_frames", scene.walkthrough.light.period_frames}};
  return j;
}

void print_text(const Scene& scene) {
  const Aabb bounds = scene.world_bounds();
  fmt::print("scene       {} ({})\n", untrusted_text(scene.name), untrusted_text(scene.source));
  fmt::print("vertices    {}\n", count_text(scene.vertex_count()));
  fmt::print("triangles   {}\n", count_text(scene.triangle_count()));
  fmt::print("bounds      min {} max {} size {}\n", vec_text(bounds.min), vec_text(bounds.max), vec_text(bounds.extent()));
  fmt::print("meshes      {} ({} instances)\n", scene.meshes.size(), scene.instances.size());
  for (const Mesh& mesh : scene.meshes)
    fmt::print("  {:<32} {:>9} vertices {:>9} triangles  {}{}\n", untrusted_text(mesh.name), count_text(mesh.vertex_count()),
               count_text(mesh.triangle_count()), untrusted_text(scene.materials[mesh.material].name), mesh.deformable ? "  [deformable]" : "");
  const auto deformable = scene.deformable_meshes();
  fmt::print("deformable  {}\n", deformable.empty() ? "none" : std::to_string(deformable.size()) + " meshes");
  for (std::uint32_t index : deformable) {
    const Mesh& mesh = scene.meshes[index];
    fmt::print("  {:<32} sine: {} += {:.3f} * sin({:.2f} * {} + {:.2f} * t)\n", untrusted_text(mesh.name), axis_name(mesh.deform->displace_axis),
               mesh.deform->amplitude, mesh.deform->frequency, axis_name(mesh.deform->wave_axis), mesh.deform->speed);
  }
  fmt::print("materials   {}\n", scene.materials.size());
  for (const Material& material : scene.materials)
    fmt::print("  {:<32} diffuse {}  reflectivity {:.2f}  shininess {:.0f}{}\n", untrusted_text(material.name), vec_text(material.diffuse),
               material.reflectivity, material.specular_exponent,
               material.diffuse_texture >= 0 ? "  texture " + untrusted_text(scene.textures[static_cast<std::size_t>(material.diffuse_texture)].name) : "");
  fmt::print("textures    {}\n", scene.textures.size());
  for (const Texture& texture : scene.textures)
    fmt::print("  {:<48} {}x{}{}\n", untrusted_text(texture.name), texture.width, texture.height, texture.placeholder ? "  (missing: checker)" : "");
  fmt::print("light       at {}  colour {}  intensity {:.1f}  range {:.1f}\n", vec_text(scene.light.position),
             vec_text(scene.light.color), scene.light.intensity, scene.light.range);
  const WalkthroughAnimation animation(scene);
  const Walkthrough& walk = scene.walkthrough;
  fmt::print("walkthrough {} frames at {:.0f} fps ({:.1f} s)\n", walk.frame_count, walk.frames_per_second,
             static_cast<float>(walk.frame_count) / walk.frames_per_second);
  if (walk.camera.is_fixed())
    fmt::print("  camera    fixed at {} looking at {}, fov {:.0f} deg\n", vec_text(walk.camera.points.front()),
               vec_text(walk.camera.targets.front()), walk.camera.fov_y_degrees);
  else
    fmt::print("  camera    {} control points, path length {:.1f} m, {:.3f} m per frame, fov {:.0f} deg\n",
               walk.camera.points.size(), animation.camera_path_length(), animation.camera_speed_per_frame(),
               walk.camera.fov_y_degrees);
  fmt::print("  light     {} points, path length {:.1f} m, there and back every {} frames\n", walk.light.points.size(),
             animation.light_path_length(), walk.light.period_frames);
}

}  // namespace

void add_info_command(CLI::App& app, InfoOptions& options) {
  CLI::App* info = app.add_subcommand("info", "Describe a scene: meshes, counts, deformables, bounds, materials, light, paths");
  info->add_option("scene", options.scene, "Preset (atrium, atrium-simple, sponza) or file (.obj, .gltf, .glb, .scene.json)")
      ->capture_default_str();
  info->add_flag("--json", options.json, "Print JSON instead of text");
  add_flat_normals_flag(*info, options.flat_normals);
}

void add_flat_normals_flag(CLI::App& command, bool& flat_normals) {
  command.add_flag("--flat-normals", flat_normals, "Compute flat instead of smooth normals where a mesh has none");
}

int run_info_command(const InfoOptions& options) {
  LoadOptions load;
  load.flat_normals = options.flat_normals;
  const Scene scene = load_scene(options.scene, load);
  if (options.json)
    fmt::print("{}\n", scene_json(scene).dump(2));
  else
    print_text(scene);
  return 0;
}

}  // namespace glint
