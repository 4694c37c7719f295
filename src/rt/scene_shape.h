#pragma once
// What a ray tracer's structures were built for (mesh sizes, which mesh each instance draws), so
// that update() can refuse a scene whose topology changed since build(): a refit, or a partial
// rebuild, is only valid for the same triangles.
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace glint::rt {

struct SceneShape {
  std::vector<size_t> mesh_vertices;
  std::vector<size_t> mesh_triangles;
  std::vector<uint32_t> instance_meshes;
};

SceneShape scene_shape(const Scene& scene);

// glint::Error naming `backend` when `scene` no longer has the shape the structures were built for
// (mesh or instance count, an instance's mesh, a dirty mesh's vertex or triangle count) or a dirty
// mesh index is out of range.
void check_update(std::string_view backend, const SceneShape& built, const Scene& scene,
                  std::span<const uint32_t> dirty_meshes);

}  // namespace glint::rt
