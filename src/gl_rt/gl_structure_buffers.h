#pragma once
// The gl backend's structures in GL buffers (the layout shaders/include/gl_rt_structures.glsl reads):
//   nodes           accel::BvhNode[]: the TLAS's region first, then one region per mesh's BLAS; the
//                   walk reads it through a buffer texture (gl_rt_bindings.h, kNodeTextureUnit)
//   tlas_refs       uint[]: the TLAS leaves' instance indices
//   vertices        vec4[]: every mesh's object-space positions (w unused), mesh after mesh
//   leaf_triangles  uvec4[]: per BLAS a region of its leaf slots in the BVH's primitive order, each
//                   the triangle of that slot: its corners' indices into vertices (the mesh's offset
//                   added) and, in w, its index in the mesh. The walk reads a leaf's triangles with
//                   one load each instead of a primitive index and then the triangle's indices.
//   instances       GlInstanceRecord[]: per Scene instance its world-to-object transform and where
//                   its BLAS is
// and for the GPU refit (gl_refit.h), which only it reads:
//   links           uvec2[] beside nodes: each node's parent (its index in its own BVH, kNoParent at a
//                   root) and its arrival counter (0 between refits), written with the node's BVH
//   transforms      mat4[]: per instance its object-to-world transform (its world box's rule)
// Node indices inside a region stay local to their BVH (the walk adds the region's offset), so the
// nodes are uploaded as accel built them. A region has room for the largest BVH its mesh can get
// without split references (2 n - 1 nodes, n slots for n triangles), so an update writes the dirty
// meshes' ranges in place with glNamedBufferSubData: vertices and nodes, and the leaf slots only after
// a rebuild (a refit keeps the primitive order); a BVH that outgrows its region (sbvh's duplicated
// references) makes the whole layout be made again. The parent links are computed once per layout of
// a BVH (build, a host rebuild, every TLAS the host builds), so a GPU refit only reads them.
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
  uint32_t node_offset = 0;  // the BLAS's root in the node array
  uint32_t slot_offset = 0;  // its first leaf slot
  uint32_t node_count = 0;   // 0: an empty BLAS
  uint32_t unused = 0;
};
static_assert(sizeof(GlInstanceRecord) == 80 && std::is_trivially_copyable_v<GlInstanceRecord>);

// An index in the links of a BVH's root: it has no parent.
inline constexpr uint32_t kNoParent = 0xFFFFFFFFu;

class GlStructureBuffers {
public:
  // Where a mesh's BLAS and geometry are: its region of the node array (node_count of its
  // node_capacity nodes in use) and of the leaf slots, and its vertices.
  struct BlasRegion {
    uint32_t node_offset = 0, node_capacity = 0, node_count = 0;
    uint32_t slot_offset = 0, slot_capacity = 0;
    uint32_t vertex_offset = 0, vertex_count = 0;
  };

  // Lays out and uploads everything: every BLAS of `meshes`, their geometry, the TLAS and the
  // instances (new buffers). Needs the GL context current.
  void upload_all(const MeshBlases& meshes, const accel::Tlas& tlas);

  // After MeshBlases::update(dirty_meshes) returned `rebuilt` and the TLAS was built again: uploads
  // the dirty meshes' vertices and BLAS nodes (and leaf slots where rebuilt), the TLAS and every
  // instance record; only those ranges of the buffers are written. Falls back to upload_all when a
  // rebuilt BLAS outgrew its region.
  void upload_update(const MeshBlases& meshes, std::span<const uint32_t> dirty_meshes, const std::vector<bool>& rebuilt,
                     const accel::Tlas& tlas);

  // Binds the buffers at their binding points and the nodes' texture at its unit (gl_rt_bindings.h).
  void bind() const;
  // Binds what the GPU refit reads and writes at its bindings (gl_rt_bindings.h, kRefit*).
  void bind_for_refit() const;

  // The positions of `mesh` as the vertex buffer holds them now (a GPU deformer's), read back: the host
  // waits for the GPU, so only a host rebuild of a GPU-posed mesh does this.
  std::vector<vec3> read_positions(uint32_t mesh) const;

  const BlasRegion& region(uint32_t mesh) const { return regions_[mesh]; }
  size_t mesh_count() const { return regions_.size(); }
  GLuint nodes() const { return nodes_.id(); }
  GLuint links() const { return links_.id(); }
  GLuint vertices() const { return vertices_.id(); }

  uint32_t tlas_node_count() const { return tlas_node_count_; }
  // Bytes of the seven buffers.
  uint64_t bytes() const { return bytes_; }

private:
  bool fits(const MeshBlases& meshes, uint32_t mesh) const;
  // The leaf slots of mesh `mesh`'s BVH as leaf_triangles entries.
  void gather_leaf_triangles(const MeshBlases& meshes, uint32_t mesh, std::vector<glm::uvec4>& out) const;
  void upload_tlas_and_instances(const MeshBlases& meshes, const accel::Tlas& tlas);
  // The parent links of `bvh` (counters 0) into links_ at its region's first node.
  void write_links(const accel::Bvh& bvh, uint32_t node_offset);

  std::vector<BlasRegion> regions_;
  uint32_t tlas_node_capacity_ = 0;
  uint32_t tlas_ref_capacity_ = 0;
  uint32_t tlas_node_count_ = 0;
  GlBuffer nodes_, tlas_refs_, vertices_, leaf_triangles_, instances_, links_, transforms_;
  GlTexture node_texels_;  // a buffer texture over nodes_
  uint64_t bytes_ = 0;
  std::vector<vec4> vertex_scratch_;          // a dirty mesh's positions widened to vec4 for the upload
  std::vector<glm::uvec4> leaf_scratch_;      // a rebuilt mesh's leaf slots
  std::vector<glm::uvec2> link_scratch_;      // a BVH's parent links
};

}  // namespace glint::gl_rt
