#include "scene/append_scene.h"

#include <string>

namespace glint {
namespace {

std::string prefixed(std::string_view prefix, const std::string& name) {
  return prefix.empty() ? name : std::string(prefix) + "/" + name;
}

std::uint32_t count32(std::size_t n) { return static_cast<std::uint32_t>(n); }

}  // namespace

AppendedPart append_scene(Scene& into, const Scene& part, const mat4& transform, std::string_view name_prefix) {
  AppendedPart where;
  const int first_texture = static_cast<int>(into.textures.size());
  where.first_material = count32(into.materials.size());
  where.material_count = count32(part.materials.size());
  where.first_mesh = count32(into.meshes.size());
  where.mesh_count = count32(part.meshes.size());

  into.textures.insert(into.textures.end(), part.textures.begin(), part.textures.end());
  for (Material material : part.materials) {
    if (material.diffuse_texture >= 0) material.diffuse_texture += first_texture;
    into.materials.push_back(std::move(material));
  }
  for (Mesh mesh : part.meshes) {
    mesh.material += where.first_material;
    mesh.name = prefixed(name_prefix, mesh.name);
    into.meshes.push_back(std::move(mesh));
  }
  append_instances(into, part, where, transform, name_prefix);
  return where;
}

void append_instances(Scene& into, const Scene& part, const AppendedPart& where, const mat4& transform,
                      std::string_view name_prefix) {
  for (const Instance& instance : part.instances) {
    Instance placed = instance;
    placed.mesh = instance.mesh + where.first_mesh;
    placed.transform = transform * instance.transform;  // the part's own placement first, then ours
    placed.name = prefixed(name_prefix, instance.name);
    into.instances.push_back(std::move(placed));
  }
}

}  // namespace glint
