#include "scene/scene.h"

#include "core/error.h"
#include "scene/camera_path.h"

#include <cmath>

namespace glint {

Aabb Mesh::bounds() const {
  Aabb box;
  for (const vec3& p : positions) box.extend(p);
  return box;
}

std::size_t Scene::vertex_count() const {
  std::size_t total = 0;
  for (const Instance& instance : instances) total += meshes[instance.mesh].vertex_count();
  return total;
}

std::size_t Scene::triangle_count() const {
  std::size_t total = 0;
  for (const Instance& instance : instances) total += meshes[instance.mesh].triangle_count();
  return total;
}

Aabb Scene::world_bounds() const {
  Aabb box;
  for (const Instance& instance : instances) box.extend(transform_aabb(instance.transform, meshes[instance.mesh].bounds()));
  return box;
}

std::vector<std::uint32_t> Scene::deformable_meshes() const {
  std::vector<std::uint32_t> result;
  for (std::uint32_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].deformable) result.push_back(i);
  return result;
}

void Scene::validate() const {
  if (instances.empty() || triangle_count() == 0) fail("{}: the scene is empty (no triangles to render)", source);
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    const std::size_t n = mesh.positions.size();
    if (mesh.indices.size() % 3 != 0)
      fail("{}: mesh '{}': index count {} is not a multiple of 3", source, mesh.name, mesh.indices.size());
    if (mesh.normals.size() != n)
      fail("{}: mesh '{}': {} normals for {} positions", source, mesh.name, mesh.normals.size(), n);
    if (!mesh.uvs.empty() && mesh.uvs.size() != n)
      fail("{}: mesh '{}': {} UVs for {} positions", source, mesh.name, mesh.uvs.size(), n);
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= n)
        fail("{}: mesh '{}': triangle {} uses vertex {} but the mesh has {} vertices", source, mesh.name, i / 3,
             mesh.indices[i], n);
    for (std::size_t v = 0; v < n; ++v) {
      if (!is_finite(mesh.positions[v]))
        fail("{}: mesh '{}': vertex {} has a non-finite position", source, mesh.name, v);
      if (!is_finite(mesh.normals[v])) fail("{}: mesh '{}': vertex {} has a non-finite normal", source, mesh.name, v);
    }
    if (mesh.material >= materials.size())
      fail("{}: mesh '{}': material {} out of range ({} materials)", source, mesh.name, mesh.material,
           materials.size());
    if (mesh.deformable && !mesh.deform) fail("{}: mesh '{}': deformable but has no deformer", source, mesh.name);
  }
  for (const Material& material : materials)
    if (material.diffuse_texture >= static_cast<int>(textures.size()))
      fail("{}: material '{}': texture {} out of range ({} textures)", source, material.name,
           material.diffuse_texture, textures.size());
  for (const Instance& instance : instances)
    if (instance.mesh >= meshes.size())
      fail("{}: instance '{}': mesh {} out of range ({} meshes)", source, instance.name, instance.mesh, meshes.size());
  try {
    const WalkthroughAnimation paths(*this);  // checks the camera and light paths can be animated
  } catch (const Error& e) {
    fail("{}: {}", source, e.what());
  }
}

}  // namespace glint
