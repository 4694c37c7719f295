#include "gl_rt/gl_structure_buffers.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl_rt/gl_rt_bindings.h"

#include <algorithm>
#include <limits>

namespace glint::gl_rt {
namespace {

// Room for any BVH over `count` primitives without split references: 2 count - 1 nodes.
uint32_t node_room(size_t count) { return count == 0 ? 0 : static_cast<uint32_t>(2 * count - 1); }

uint32_t checked_u32(size_t value, const char* what) {
  if (value > std::numeric_limits<uint32_t>::max())
    fail("rt gl: {} {} exceed the 32-bit indices of the GL structures", value, what);
  return static_cast<uint32_t>(value);
}

// An immutable buffer the host may overwrite in parts (glNamedBufferSubData); never empty, so a scene
// without a region still binds something.
template <typename T>
GlBuffer make_storage(const std::vector<T>& data) {
  return create_nonempty_buffer(std::span<const T>(data), GL_DYNAMIC_STORAGE_BIT);
}

template <typename T>
void write(const GlBuffer& buffer, size_t first, std::span<const T> data) {
  if (data.empty()) return;
  glNamedBufferSubData(buffer.id(), static_cast<GLintptr>(first * sizeof(T)), static_cast<GLsizeiptr>(data.size_bytes()),
                       data.data());
}

// A buffer texture of RGBA32UI texels over `buffer`, two a node; glint::Error when the nodes need more
// texels than this GL's texture buffers hold (GL_MAX_TEXTURE_BUFFER_SIZE: 2^27 on NVIDIA, 67 M nodes).
GlTexture node_texture(const GlBuffer& buffer, size_t nodes) {
  GLint max_texels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_texels);
  if (2 * nodes > static_cast<size_t>(max_texels))
    fail("rt gl: {} BVH nodes need {} texels, more than this GL's texture buffers hold ({})", nodes, 2 * nodes,
         max_texels);
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
  GlTexture texture(id);
  glTextureBuffer(texture.id(), GL_RGBA32UI, buffer.id());
  return texture;
}

}  // namespace

bool GlStructureBuffers::fits(const MeshBlases& meshes, uint32_t mesh) const {
  const accel::Bvh& bvh = meshes.meshes()[mesh].bvh;
  return bvh.nodes.size() <= regions_[mesh].node_capacity && bvh.prim_indices.size() <= regions_[mesh].slot_capacity;
}

void GlStructureBuffers::gather_leaf_triangles(const MeshBlases& meshes, uint32_t mesh,
                                               std::vector<glm::uvec4>& out) const {
  const MeshBlases::Mesh& source = meshes.meshes()[mesh];
  const uint32_t base = regions_[mesh].vertex_offset;
  out.clear();
  out.reserve(source.bvh.prim_indices.size());
  for (const uint32_t prim : source.bvh.prim_indices) {
    const uint32_t* corner = &source.indices[3 * static_cast<size_t>(prim)];
    out.emplace_back(base + corner[0], base + corner[1], base + corner[2], prim);
  }
}

void GlStructureBuffers::upload_all(const MeshBlases& meshes, const accel::Tlas& tlas) {
  const std::vector<MeshBlases::Mesh>& all = meshes.meshes();
  const size_t instance_count = tlas.instances.size();
  tlas_node_capacity_ = std::max(checked_u32(tlas.bvh.nodes.size(), "TLAS nodes"), node_room(instance_count));
  tlas_ref_capacity_ = std::max(checked_u32(tlas.bvh.prim_indices.size(), "TLAS references"),
                                checked_u32(instance_count, "instances"));
  regions_.assign(all.size(), {});
  size_t nodes = tlas_node_capacity_, slots = 0, vertices = 0;
  for (size_t m = 0; m < all.size(); ++m) {
    const size_t triangle_count = all[m].indices.size() / 3;
    BlasRegion& region = regions_[m];
    region.node_offset = checked_u32(nodes, "BVH nodes");
    region.node_capacity = std::max(checked_u32(all[m].bvh.nodes.size(), "BVH nodes"), node_room(triangle_count));
    region.node_count = static_cast<uint32_t>(all[m].bvh.nodes.size());
    region.slot_offset = checked_u32(slots, "BVH references");
    region.slot_capacity =
        std::max(checked_u32(all[m].bvh.prim_indices.size(), "BVH references"), checked_u32(triangle_count, "triangles"));
    region.vertex_offset = checked_u32(vertices, "vertices");
    region.vertex_count = checked_u32(all[m].positions.size(), "vertices");
    nodes += region.node_capacity;
    slots += region.slot_capacity;
    vertices += all[m].positions.size();
  }
  (void)checked_u32(nodes, "BVH nodes");
  (void)checked_u32(slots, "BVH references");
  (void)checked_u32(vertices, "vertices");

  std::vector<accel::BvhNode> node_data(nodes);
  std::vector<glm::uvec4> leaf_data(slots, glm::uvec4(0u));
  std::vector<vec4> vertex_data;
  vertex_data.reserve(vertices);
  for (uint32_t m = 0; m < all.size(); ++m) {
    const MeshBlases::Mesh& mesh = all[m];
    std::copy(mesh.bvh.nodes.begin(), mesh.bvh.nodes.end(), node_data.begin() + regions_[m].node_offset);
    gather_leaf_triangles(meshes, m, leaf_scratch_);
    std::copy(leaf_scratch_.begin(), leaf_scratch_.end(), leaf_data.begin() + regions_[m].slot_offset);
    for (const vec3& p : mesh.positions) vertex_data.emplace_back(p, 1.0f);
  }
  nodes_ = make_storage(node_data);
  node_texels_ = node_texture(nodes_, std::max<size_t>(nodes, 1));
  tlas_refs_ = make_storage(std::vector<uint32_t>(tlas_ref_capacity_, 0u));
  vertices_ = make_storage(vertex_data);
  leaf_triangles_ = make_storage(leaf_data);
  instances_ = make_storage(std::vector<GlInstanceRecord>(instance_count));
  // Counters start at 0; the links of every BVH are written below and by upload_tlas_and_instances.
  links_ = make_storage(std::vector<glm::uvec2>(nodes, glm::uvec2(kNoParent, 0u)));
  transforms_ = make_storage(std::vector<mat4>(instance_count, mat4(1.0f)));
  for (uint32_t m = 0; m < all.size(); ++m) write_links(all[m].bvh, regions_[m].node_offset);
  bytes_ = std::max<size_t>(nodes, 1) * (sizeof(accel::BvhNode) + sizeof(glm::uvec2)) +
           std::max<size_t>(tlas_ref_capacity_, 1) * sizeof(uint32_t) + std::max<size_t>(vertices, 1) * sizeof(vec4) +
           std::max<size_t>(slots, 1) * sizeof(glm::uvec4) +
           std::max<size_t>(instance_count, 1) * (sizeof(GlInstanceRecord) + sizeof(mat4));
  upload_tlas_and_instances(meshes, tlas);
  check_gl("rt gl: uploading the structures");
}

void GlStructureBuffers::upload_update(const MeshBlases& meshes, std::span<const uint32_t> dirty_meshes,
                                       const std::vector<bool>& rebuilt, const accel::Tlas& tlas) {
  for (uint32_t m : dirty_meshes) {
    if (!fits(meshes, m)) {
      upload_all(meshes, tlas);
      return;
    }
  }
  for (size_t i = 0; i < dirty_meshes.size(); ++i) {
    const uint32_t m = dirty_meshes[i];
    const MeshBlases::Mesh& mesh = meshes.meshes()[m];
    vertex_scratch_.clear();
    for (const vec3& p : mesh.positions) vertex_scratch_.emplace_back(p, 1.0f);
    write(vertices_, regions_[m].vertex_offset, std::span<const vec4>(vertex_scratch_));
    write(nodes_, regions_[m].node_offset, std::span<const accel::BvhNode>(mesh.bvh.nodes.data(), mesh.bvh.nodes.size()));
    // A refit keeps the primitive order and the topology, so the leaf slots and the parent links only
    // change with a rebuild.
    if (rebuilt[i]) {
      gather_leaf_triangles(meshes, m, leaf_scratch_);
      write(leaf_triangles_, regions_[m].slot_offset, std::span<const glm::uvec4>(leaf_scratch_));
      write_links(mesh.bvh, regions_[m].node_offset);
      regions_[m].node_count = static_cast<uint32_t>(mesh.bvh.nodes.size());
    }
  }
  upload_tlas_and_instances(meshes, tlas);
  check_gl("rt gl: uploading the updated structures");
}

void GlStructureBuffers::upload_tlas_and_instances(const MeshBlases& meshes, const accel::Tlas& tlas) {
  // The TLAS over n instances has at most 2 n - 1 nodes and n references (no splits): always fits.
  if (tlas.bvh.nodes.size() > tlas_node_capacity_ || tlas.bvh.prim_indices.size() > tlas_ref_capacity_)
    fail("rt gl: the TLAS ({} nodes, {} references) outgrew its region ({}, {})", tlas.bvh.nodes.size(),
         tlas.bvh.prim_indices.size(), tlas_node_capacity_, tlas_ref_capacity_);
  write(nodes_, 0, std::span<const accel::BvhNode>(tlas.bvh.nodes.data(), tlas.bvh.nodes.size()));
  write(tlas_refs_, 0, std::span<const uint32_t>(tlas.bvh.prim_indices.data(), tlas.bvh.prim_indices.size()));
  tlas_node_count_ = static_cast<uint32_t>(tlas.bvh.nodes.size());
  // The host builds a new TLAS with every upload: its links too, so the GPU refit keeps its topology.
  write_links(tlas.bvh, 0);
  std::vector<mat4> transforms(tlas.instances.size());
  std::vector<GlInstanceRecord> records(tlas.instances.size());
  for (size_t i = 0; i < records.size(); ++i) {
    const accel::Instance& instance = tlas.instances[i];
    const BlasRegion& region = regions_[instance.blas];
    records[i].world_to_object = instance.world_to_object;
    records[i].node_offset = region.node_offset;
    records[i].slot_offset = region.slot_offset;
    records[i].node_count = static_cast<uint32_t>(meshes.meshes()[instance.blas].bvh.nodes.size());
    transforms[i] = instance.object_to_world;
  }
  write(instances_, 0, std::span<const GlInstanceRecord>(records));
  write(transforms_, 0, std::span<const mat4>(transforms));
}

void GlStructureBuffers::write_links(const accel::Bvh& bvh, uint32_t node_offset) {
  link_scratch_.assign(bvh.nodes.size(), glm::uvec2(kNoParent, 0u));
  for (uint32_t node = 0; node < bvh.nodes.size(); ++node) {
    const accel::BvhNode& interior = bvh.nodes[node];
    if (interior.is_leaf()) continue;
    link_scratch_[interior.left()].x = node;
    link_scratch_[interior.right()].x = node;
  }
  write(links_, node_offset, std::span<const glm::uvec2>(link_scratch_));
}

std::vector<vec3> GlStructureBuffers::read_positions(uint32_t mesh) const {
  const BlasRegion& region = regions_[mesh];
  std::vector<vec4> widened(region.vertex_count);
  // Shader writes (the deformer's) reach a buffer read only past this barrier.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  if (!widened.empty())
    glGetNamedBufferSubData(vertices_.id(), static_cast<GLintptr>(std::size_t{region.vertex_offset} * sizeof(vec4)),
                            static_cast<GLsizeiptr>(widened.size() * sizeof(vec4)), widened.data());
  check_gl("rt gl: reading positions back");
  std::vector<vec3> positions;
  positions.reserve(widened.size());
  for (const vec4& p : widened) positions.emplace_back(p);
  return positions;
}

void GlStructureBuffers::bind() const {
  glBindTextureUnit(kNodeTextureUnit, node_texels_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTlasRefBinding, tlas_refs_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexBinding, vertices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLeafTriangleBinding, leaf_triangles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, instances_.id());
}

void GlStructureBuffers::bind_for_refit() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTlasRefBinding, tlas_refs_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexBinding, vertices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLeafTriangleBinding, leaf_triangles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, instances_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRefitNodeBinding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRefitLinkBinding, links_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRefitTransformBinding, transforms_.id());
}

}  // namespace glint::gl_rt
