#include "render/shadow_chunks.h"

#include "accel/builders/builder.h"
#include "accel/triangle_mesh.h"
#include "core/error.h"

#include <span>

namespace glint::render {
namespace {

// A static mesh's triangles, re-indexed chunk by chunk.
struct MeshChunks {
  std::vector<std::uint32_t> indices;  // mesh-local vertex indices, chunk after chunk
  struct Range {
    std::uint32_t first_triangle = 0;
    std::uint32_t triangle_count = 0;
    Aabb object_box;
  };
  std::vector<Range> ranges;
};

MeshChunks chunk_mesh(const Mesh& mesh) {
  MeshChunks result;
  if (mesh.triangle_count() == 0) return result;
  accel::BuildOptions options;
  options.max_leaf_size = kShadowChunkTriangles;
  const accel::Bvh bvh =
      accel::build_bvh(accel::BvhBuilder::median, accel::make_indexed_mesh(mesh.positions, mesh.indices), options);
  // Leaves in node order; each covers a contiguous range of prim_indices, which lists every
  // triangle exactly once.
  for (const accel::BvhNode& node : bvh.nodes) {
    if (!node.is_leaf()) continue;
    result.ranges.push_back({static_cast<std::uint32_t>(result.indices.size() / 3), node.prim_count, node.bounds()});
    for (std::uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot) {
      const std::uint32_t triangle = bvh.prim_indices[slot];
      for (int corner = 0; corner < 3; ++corner) result.indices.push_back(mesh.indices[3 * triangle + corner]);
    }
  }
  return result;
}

}  // namespace

ShadowChunks::ShadowChunks(const Scene& scene, const GpuScene& gpu) {
  const std::vector<GpuMeshRange>& ranges = gpu.mesh_ranges();
  if (ranges.size() != scene.meshes.size() || gpu.instances().size() != scene.instances.size())
    fail("shadow chunks: the GPU scene was uploaded from another scene");
  // Every mesh's triangles once, in this buffer's order: static meshes chunk by chunk, deformable
  // ones as they are.
  std::vector<std::uint32_t> index_data;
  std::vector<std::uint32_t> mesh_first_index(scene.meshes.size());
  std::vector<MeshChunks> mesh_chunks(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    mesh_first_index[m] = static_cast<std::uint32_t>(index_data.size());
    if (mesh.deformable) {
      index_data.insert(index_data.end(), mesh.indices.begin(), mesh.indices.end());
      continue;
    }
    mesh_chunks[m] = chunk_mesh(mesh);
    index_data.insert(index_data.end(), mesh_chunks[m].indices.begin(), mesh_chunks[m].indices.end());
    mesh_chunks[m].indices = {};
  }
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    const Mesh& mesh = scene.meshes[instance.mesh];
    const GpuMeshRange& range = ranges[instance.mesh];
    const auto base_vertex = static_cast<GLint>(range.base_vertex);
    const auto base_instance = static_cast<GLuint>(i);
    if (mesh.deformable) {
      chunks_.push_back({{range.index_count, 1, mesh_first_index[instance.mesh], base_vertex, base_instance}, std::nullopt});
      continue;
    }
    for (const MeshChunks::Range& chunk : mesh_chunks[instance.mesh].ranges)
      chunks_.push_back({{3 * chunk.triangle_count, 1, mesh_first_index[instance.mesh] + 3 * chunk.first_triangle,
                          base_vertex, base_instance},
                         transform_aabb(instance.transform, chunk.object_box)});
  }
  indices_ = create_buffer(std::span<const std::uint32_t>(index_data));
}

}  // namespace glint::render
