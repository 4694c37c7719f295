#pragma once
// The scene's world-space bounds for each frame (the camera's clip range, the shadow cube's near
// distance: make_frame_constants), without scanning every vertex every frame. Scene::world_bounds()
// does scan them all: 332,594 vertices of the atrium, on the host, in every frame's path. Here each
// mesh's object-space box is kept and scanned again only when its vertices can have changed: every
// frame for a deformable mesh (Mesh::deformable: posed each frame), and for any other mesh when
// GpuScene::update_mesh_vertices replaced its vertices (GpuScene::vertex_version). The instances'
// boxes are combined every frame (one per instance), so moved instances are followed too. The result
// equals Scene::world_bounds() whenever the scene's host vertices and the GPU's agree (tests/render/
// scene_world_bounds_test.cpp); a caller that changes a static mesh's host vertices without uploading
// them has a GPU picture that does not show them either.
#include "core/math.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::render {

class SceneWorldBounds {
public:
  // The bounds of `scene`, whose vertices `gpu_scene` holds; the same pair at every call.
  Aabb of(const Scene& scene, const GpuScene& gpu_scene);

private:
  struct MeshBox {
    std::optional<Aabb> box;      // object space; nullopt until first scanned
    std::uint64_t version = 0;    // GpuScene::vertex_version when scanned
  };
  std::vector<MeshBox> meshes_;
};

}  // namespace glint::render
