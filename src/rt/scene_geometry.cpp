#include "rt/scene_geometry.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace glint::rt {
namespace {

constexpr size_t kMaxElements = std::numeric_limits<uint32_t>::max() - 1;

// World positions of `mesh` under `transform`, written to out[0 .. vertex_count). Parallel: the
// creatures are rewritten every frame and have tens of thousands of vertices.
void transform_positions(const Mesh& mesh, const mat4& transform, vec3* out) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.positions.size(), 4096), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) out[i] = vec3(transform * vec4(mesh.positions[i], 1.0f));
  });
}

SceneGeometry flatten(const Scene& scene, const std::vector<bool>& keep_mesh) {
  scene.validate();
  SceneGeometry geometry;
  size_t vertices = 0, triangles = 0;
  for (const Instance& instance : scene.instances) {
    if (!keep_mesh[instance.mesh]) continue;
    vertices += scene.meshes[instance.mesh].vertex_count();
    triangles += scene.meshes[instance.mesh].triangle_count();
  }
  if (vertices > kMaxElements || triangles > kMaxElements)
    fail("scene '{}': {} world vertices and {} triangles exceed the 2^32 - 2 a flat triangle list can index",
         scene.name, vertices, triangles);
  geometry.positions.resize(vertices);
  geometry.indices.reserve(3 * triangles);
  geometry.sources.reserve(triangles);

  uint32_t first_vertex = 0;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (!keep_mesh[instance.mesh]) continue;
    const Mesh& mesh = scene.meshes[instance.mesh];
    InstanceRange range;
    range.instance = i;
    range.mesh = instance.mesh;
    range.first_vertex = first_vertex;
    range.vertex_count = static_cast<uint32_t>(mesh.vertex_count());
    range.first_triangle = static_cast<uint32_t>(geometry.sources.size());
    range.triangle_count = static_cast<uint32_t>(mesh.triangle_count());
    transform_positions(mesh, instance.transform, geometry.positions.data() + first_vertex);
    for (uint32_t index : mesh.indices) geometry.indices.push_back(first_vertex + index);
    for (uint32_t t = 0; t < range.triangle_count; ++t) geometry.sources.push_back({i, instance.mesh, t});
    geometry.instances.push_back(range);
    if (mesh.deformable) geometry.deformable.push_back(range);
    first_vertex += range.vertex_count;
  }
  return geometry;
}

}  // namespace

accel::TriangleMesh SceneGeometry::mesh() const { return accel::make_indexed_mesh(positions, indices); }

Aabb SceneGeometry::bounds() const {
  Aabb box;
  for (const vec3& p : positions) box.extend(p);
  return box;
}

SceneGeometry flatten_scene(const Scene& scene) { return flatten(scene, std::vector<bool>(scene.meshes.size(), true)); }

SceneGeometry flatten_scene(const Scene& scene, std::span<const uint32_t> mesh_indices) {
  std::vector<bool> keep(scene.meshes.size(), false);
  for (uint32_t mesh : mesh_indices) {
    if (mesh >= scene.meshes.size())
      fail("scene '{}': mesh index {} out of range ({} meshes)", scene.name, mesh, scene.meshes.size());
    keep[mesh] = true;
  }
  return flatten(scene, keep);
}

void update_deformed(SceneGeometry& geometry, const Scene& scene, std::span<const uint32_t> dirty_meshes) {
  for (uint32_t mesh_index : dirty_meshes) {
    if (mesh_index >= scene.meshes.size())
      fail("scene '{}': dirty mesh index {} out of range ({} meshes)", scene.name, mesh_index, scene.meshes.size());
    const Mesh& mesh = scene.meshes[mesh_index];
    for (const InstanceRange& range : geometry.instances) {
      if (range.mesh != mesh_index) continue;
      if (mesh.vertex_count() != range.vertex_count || mesh.triangle_count() != range.triangle_count)
        fail("scene '{}': mesh '{}' has {} vertices and {} triangles, flattened with {} and {}", scene.name, mesh.name,
             mesh.vertex_count(), mesh.triangle_count(), range.vertex_count, range.triangle_count);
      transform_positions(mesh, scene.instances[range.instance].transform, geometry.positions.data() + range.first_vertex);
    }
  }
}

}  // namespace glint::rt
