#pragma once
// ShadowChunks: the scene cut into spatially compact pieces for the shadow cube map, so that each
// face draws only the pieces that may reach into its frustum. An instance is one piece per face
// otherwise, and the atrium's whole-building meshes (floor, walls, columns) reach into every face.
//
// Each static mesh's triangles are split by object-median cuts on the longest axis (accel's
// `median` builder with leaves of at most kShadowChunkTriangles) and re-indexed leaf by leaf into an
// index buffer of this class's own: a chunk is a contiguous range of it, with its box. The scene's
// own index buffer keeps its order (ray hits name triangles by it). Deformable meshes stay whole
// and have no box: the GPU deformer moves their vertices where a box would not follow, so they are
// drawn into every face.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::render {

inline constexpr std::uint32_t kShadowChunkTriangles = 4096;

struct ShadowChunk {
  DrawElementsIndirectCommand command;  // into index_buffer(), with the scene's vertices and instance
  std::optional<Aabb> world_box;        // nullopt: deformable, drawn into every face
};

class ShadowChunks {
public:
  // Needs a current GL context (uploads the index buffer). `gpu` is the same scene uploaded.
  ShadowChunks(const Scene& scene, const GpuScene& gpu);

  const std::vector<ShadowChunk>& chunks() const { return chunks_; }
  GLuint index_buffer() const { return indices_.id(); }

private:
  std::vector<ShadowChunk> chunks_;
  GlBuffer indices_;
};

}  // namespace glint::render
