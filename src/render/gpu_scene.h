#pragma once
// A Scene uploaded to the GPU once: every mesh's vertices in one buffer, every index in one buffer,
// materials, instances and textures in buffers/arrays that any shader (draw or compute) can index.
// Deformable meshes update their positions and normals in place each frame.
//
// Layout (std430, also what the ray-traced hit shading reads; docs/render.md has the GLSL):
//   vertices  (kVertexBufferBinding):   GpuVertex[]   { vec4 position_u; vec4 normal_v; }
//             mesh m's vertex i is vertices[mesh_ranges[m].base_vertex + i]
//   indices   (kIndexBufferBinding):    uint[]        mesh-local vertex indices, 3 per triangle;
//             triangle p of mesh m is indices[mesh_ranges[m].first_index + 3p + 0..2]
//   meshes    (kMeshRangeBinding):      GpuMeshRange[] { uint first_index, index_count, base_vertex, vertex_count; }
//   instances (kInstanceBinding):       GpuInstance[]  { mat4 model; mat4 normal_matrix; uint mesh, material, pad, pad; }
//   materials (kMaterialBinding):       GpuMaterial[]  (see below)
//   textures  (kMaterialTextureUnit):   sampler2DArray, GL_SRGB8_ALPHA8, layer = Scene texture index
// A hit record {instance, prim, u, v} is shaded from these alone.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::render {

// Shader storage binding points of the scene buffers (shared by every pass that reads the scene).
inline constexpr GLuint kVertexBufferBinding = 1;
inline constexpr GLuint kIndexBufferBinding = 2;
inline constexpr GLuint kMeshRangeBinding = 3;
inline constexpr GLuint kInstanceBinding = 4;
inline constexpr GLuint kMaterialBinding = 5;
// Texture unit of the material texture array (sampler2DArray).
inline constexpr GLuint kMaterialTextureUnit = 0;

// One vertex, interleaved so a vertex is one 32-byte fetch; uv rides in the spare w components.
struct GpuVertex {
  vec4 position_u{0.0f};  // xyz object-space position, w = u
  vec4 normal_v{0.0f};    // xyz object-space unit normal, w = v
};
static_assert(sizeof(GpuVertex) == 32);

struct GpuMeshRange {
  std::uint32_t first_index = 0;   // into the index buffer
  std::uint32_t index_count = 0;   // 3 per triangle
  std::uint32_t base_vertex = 0;   // into the vertex buffer; indices are relative to it
  std::uint32_t vertex_count = 0;
};
static_assert(sizeof(GpuMeshRange) == 16);

struct GpuInstance {
  mat4 model{1.0f};          // object to world
  mat4 normal_matrix{1.0f};  // inverse transpose of model's upper 3x3 (in a mat4 for std430)
  std::uint32_t mesh = 0;
  std::uint32_t material = 0;
  std::uint32_t padding[2] = {0, 0};
};
static_assert(sizeof(GpuInstance) == 144);

struct GpuMaterial {
  vec4 diffuse{0.0f};            // rgb linear, a unused
  vec4 specular_exponent{0.0f};  // rgb specular colour, w = Blinn-Phong exponent
  vec4 emissive{0.0f};           // rgb linear, a unused
  float reflectivity = 0.0f;
  float roughness = 0.0f;
  std::int32_t texture_layer = -1;  // layer of the texture array, -1 = no texture
  std::int32_t padding = 0;
};
static_assert(sizeof(GpuMaterial) == 64);

// glMultiDrawElementsIndirect's command layout (fixed by the GL specification).
struct DrawElementsIndirectCommand {
  GLuint count;
  GLuint instance_count;
  GLuint first_index;
  GLint base_vertex;
  GLuint base_instance;
};
static_assert(sizeof(DrawElementsIndirectCommand) == 20);

struct GpuSceneOptions {
  int max_texture_layer_size = 1024;  // layers are square: the largest texture side, clamped to this
};

class GpuScene {
public:
  // Uploads everything; needs a current GL context. Throws glint::Error on an invalid scene.
  explicit GpuScene(const Scene& scene, const GpuSceneOptions& options = {});

  // Replaces mesh `mesh`'s object-space positions and normals (same count as the mesh has); uvs and
  // indices stay. Throws glint::Error for an unknown mesh or a size mismatch.
  void update_mesh_vertices(std::uint32_t mesh, std::span<const vec3> positions, std::span<const vec3> normals);
  // How many times update_mesh_vertices replaced mesh `mesh`'s vertices (0 for an unknown mesh):
  // what caches of a mesh's host-side data (SceneWorldBounds) compare to know they are stale.
  std::uint64_t vertex_version(std::uint32_t mesh) const {
    return mesh < vertex_versions_.size() ? vertex_versions_[mesh] : 0;
  }

  // Binds the scene buffers to their SSBO bindings and the texture array to its unit.
  void bind_resources() const;
  // Draws every instance (one glMultiDrawElementsIndirect) with the bound program; vertex attributes:
  // 0 = vec4 position_u, 1 = vec4 normal_v, 2 = uint instance index (into the instance buffer).
  // Binds the scene's resources and vertex array first.
  void draw_all_instances() const;
  // The same for commands [first, first + count) of another indirect buffer, with this scene's
  // vertices and instances; their first_index counts in `index_buffer` when it is not 0 (another
  // order of the same triangles, as ShadowChunks keeps), else in the scene's index buffer.
  void draw_commands(GLuint command_buffer, std::size_t first, std::size_t count, GLuint index_buffer = 0) const;
  // Instance i's draw command, in instance order: what draw_all_instances draws.
  const std::vector<DrawElementsIndirectCommand>& draw_command_data() const { return draw_command_data_; }

  GLuint vertex_buffer() const { return vertices_.id(); }
  GLuint index_buffer() const { return indices_.id(); }
  GLuint mesh_range_buffer() const { return mesh_ranges_.id(); }
  GLuint instance_buffer() const { return instances_.id(); }
  GLuint material_buffer() const { return materials_.id(); }
  GLuint texture_array() const { return texture_array_.id(); }
  int texture_layer_size() const { return texture_layer_size_; }
  int texture_layer_count() const { return texture_layer_count_; }  // at least 1 (a white layer)

  const std::vector<GpuMeshRange>& mesh_ranges() const { return mesh_range_data_; }
  const std::vector<GpuInstance>& instances() const { return instance_data_; }
  const std::vector<GpuMaterial>& materials() const { return material_data_; }
  std::size_t vertex_count() const { return vertex_data_.size(); }

private:
  void upload_textures(const Scene& scene, const GpuSceneOptions& options);

  std::vector<GpuVertex> vertex_data_;  // CPU mirror: updates rewrite a mesh's range from it
  std::vector<GpuMeshRange> mesh_range_data_;
  std::vector<std::uint64_t> vertex_versions_;  // per mesh: update_mesh_vertices calls
  std::vector<GpuInstance> instance_data_;
  std::vector<GpuMaterial> material_data_;
  std::vector<DrawElementsIndirectCommand> draw_command_data_;
  GlBuffer vertices_, indices_, mesh_ranges_, instances_, materials_;
  GlBuffer instance_ids_;      // 0, 1, 2, ...: per-instance attribute 2, picked by baseInstance
  GlBuffer draw_commands_;     // DrawElementsIndirectCommand per instance
  GlVertexArray vertex_array_;
  GlTexture texture_array_;
  int texture_layer_size_ = 1;
  int texture_layer_count_ = 1;
};

}  // namespace glint::render
