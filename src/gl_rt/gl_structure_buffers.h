#pragma once
// The gl backend's structures in GL buffers (the layout shaders/include/gl_rt_structures.glsl reads):
//   nodes      accel::BvhNode[]: the TLAS's region first, then one region per mesh's BLAS
//   prims      uint[]: the primitive indices of the same BVHs, in the same order of regions
//   vertices   vec4[]: every mesh's object-space positions (w unused), mesh after mesh
//   triangles  uvec4[]: per triangle its corners' indices into vertices (w unused), mesh after mesh
//   instances  GlInstanceRecord[]: per Scene instance its world-to-object transform and where its
//              BLAS and its mesh's triangles are
// Node and primitive indices inside a region stay local to their BVH (the walk adds the region's
// offset), so a BVH is uploaded as accel built it. A region has room for the largest BVH its mesh
// can get without split references (2 n - 1 nodes, n primitive indices for n triangles), so a rebuild
// or refit is uploaded in place with glNamedBufferSubData of that region alone; a BVH that outgrows
// it (sbvh's duplicated references) makes the whole layout be made again.
#include "accel/tlas.h"
#include "gl/gl_objects.h"
#include "gl_rt/mesh_blases.h"

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace glint::gl_rt {

// std430 layout of TracerInstance in gl_rt_structures.glsl.
struct GlInstanceRecord {
  mat4 world_to_object{1.0f};
  uint32_t node_offset = 0;      // the BLAS's root in the node array
  uint32_t prim_offset = 0;      // its first primitive index
  uint32_t triangle_offset = 0;  // the mesh's first triangle
  uint32_t node_count = 0;       // 0: an empty BLAS
};
static_assert(sizeof(GlInstanceRecord) == 80 && std::is_trivially_copyable_v<GlInstanceRecord>);

class GlStructureBuffers {
public:
  // Lays out and uploads everything: every BLAS of `meshes`, their geometry, the TLAS and the
  // instances (new buffers). Needs the GL context current.
  void upload_all(const MeshBlases& meshes, const accel::Tlas& tlas);

  // After MeshBlases::update(dirty_meshes) returned `rebuilt` and the TLAS was built again: uploads
  // the dirty meshes' vertices and BLAS nodes (and primitive indices where rebuilt), the TLAS and
  // every instance record; only those ranges of the buffers are written. Falls back to upload_all
  // when a rebuilt BLAS outgrew its region.
  void upload_update(const MeshBlases& meshes, std::span<const uint32_t> dirty_meshes, const std::vector<bool>& rebuilt,
                     const accel::Tlas& tlas);

  // Binds the five buffers at their binding points (gl_rt_bindings.h).
  void bind() const;

  uint32_t tlas_node_count() const { return tlas_node_count_; }
  // Bytes of the five buffers.
  uint64_t bytes() const { return bytes_; }

private:
  struct BlasRegion {
    uint32_t node_offset = 0, node_capacity = 0;
    uint32_t prim_offset = 0, prim_capacity = 0;
  };

  bool fits(const MeshBlases& meshes, uint32_t mesh) const;
  void upload_tlas_and_instances(const MeshBlases& meshes, const accel::Tlas& tlas);

  std::vector<BlasRegion> regions_;
  std::vector<uint32_t> vertex_offsets_;    // per mesh, into the vertex array
  std::vector<uint32_t> triangle_offsets_;  // per mesh, into the triangle array
  uint32_t tlas_node_capacity_ = 0;
  uint32_t tlas_prim_capacity_ = 0;
  uint32_t tlas_node_count_ = 0;
  GlBuffer nodes_, prims_, vertices_, triangles_, instances_;
  uint64_t bytes_ = 0;
  std::vector<vec4> vertex_scratch_;  // a dirty mesh's positions widened to vec4 for the upload
};

}  // namespace glint::gl_rt
