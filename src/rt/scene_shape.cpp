#include "rt/scene_shape.h"

#include "core/error.h"

namespace glint::rt {

SceneShape scene_shape(const Scene& scene) {
  SceneShape shape;
  for (const Mesh& mesh : scene.meshes) {
    shape.mesh_vertices.push_back(mesh.vertex_count());
    shape.mesh_triangles.push_back(mesh.triangle_count());
  }
  for (const Instance& instance : scene.instances) shape.instance_meshes.push_back(instance.mesh);
  return shape;
}

void check_update(std::string_view backend, const SceneShape& built, const Scene& scene,
                  std::span<const uint32_t> dirty_meshes) {
  if (scene.meshes.size() != built.mesh_vertices.size() || scene.instances.size() != built.instance_meshes.size())
    fail("rt {}: scene '{}' has {} meshes and {} instances, the structures were built for {} and {}; build() again",
         backend, scene.name, scene.meshes.size(), scene.instances.size(), built.mesh_vertices.size(),
         built.instance_meshes.size());
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].mesh != built.instance_meshes[i])
      fail("rt {}: instance {} of scene '{}' now draws mesh {} instead of {}; build() again", backend, i, scene.name,
           scene.instances[i].mesh, built.instance_meshes[i]);
  for (uint32_t m : dirty_meshes) {
    if (m >= scene.meshes.size())
      fail("rt {}: dirty mesh index {} out of range ({} meshes)", backend, m, scene.meshes.size());
    const Mesh& mesh = scene.meshes[m];
    if (mesh.vertex_count() != built.mesh_vertices[m] || mesh.triangle_count() != built.mesh_triangles[m])
      fail("rt {}: mesh '{}' has {} vertices and {} triangles, built with {} and {}; build() again", backend,
           mesh.name, mesh.vertex_count(), mesh.triangle_count(), built.mesh_vertices[m], built.mesh_triangles[m]);
  }
}

}  // namespace glint::rt
