#include "render/scene_world_bounds.h"

namespace glint::render {

Aabb SceneWorldBounds::of(const Scene& scene, const GpuScene& gpu_scene) {
  meshes_.resize(scene.meshes.size());
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    MeshBox& cached = meshes_[m];
    const std::uint64_t version = gpu_scene.vertex_version(m);
    if (cached.box && !scene.meshes[m].deformable && cached.version == version) continue;
    cached.box = scene.meshes[m].bounds();
    cached.version = version;
  }
  // As Scene::world_bounds() combines them, so the two agree bit for bit.
  Aabb box;
  for (const Instance& instance : scene.instances)
    box.extend(transform_aabb(instance.transform, *meshes_[instance.mesh].box));
  return box;
}

}  // namespace glint::render
