#include "render/gpu_scene.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/texture_layers.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace glint::render {
namespace {

GpuMaterial to_gpu(const Material& material) {
  GpuMaterial gpu;
  gpu.diffuse = vec4(material.diffuse, 1.0f);
  gpu.specular_exponent = vec4(material.specular, material.specular_exponent);
  gpu.emissive = vec4(material.emissive, 0.0f);
  gpu.reflectivity = material.reflectivity;
  gpu.roughness = material.roughness;
  gpu.texture_layer = material.diffuse_texture;  // one layer per scene texture, same index
  return gpu;
}

std::uint32_t checked_u32(std::size_t value, const char* what) {
  if (value > std::numeric_limits<std::uint32_t>::max()) fail("GPU scene: too many {} ({})", what, value);
  return static_cast<std::uint32_t>(value);
}

}  // namespace

GpuScene::GpuScene(const Scene& scene, const GpuSceneOptions& options) {
  scene.validate();

  // Meshes: concatenate vertices and indices, remembering where each mesh starts.
  std::vector<std::uint32_t> index_data;
  for (const Mesh& mesh : scene.meshes) {
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
      fail("GPU scene: mesh '{}' has {} uvs for {} vertices", mesh.name, mesh.uvs.size(), mesh.positions.size());
    GpuMeshRange range;
    range.first_index = checked_u32(index_data.size(), "indices");
    range.index_count = checked_u32(mesh.indices.size(), "indices");
    range.base_vertex = checked_u32(vertex_data_.size(), "vertices");
    range.vertex_count = checked_u32(mesh.positions.size(), "vertices");
    mesh_range_data_.push_back(range);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const vec2 uv = mesh.uvs.empty() ? vec2(0.0f) : mesh.uvs[i];
      vertex_data_.push_back({vec4(mesh.positions[i], uv.x), vec4(mesh.normals[i], uv.y)});
    }
    index_data.insert(index_data.end(), mesh.indices.begin(), mesh.indices.end());
  }
  checked_u32(index_data.size(), "indices");
  vertex_versions_.assign(mesh_range_data_.size(), 0);

  for (const Material& material : scene.materials) material_data_.push_back(to_gpu(material));

  std::vector<DrawElementsIndirectCommand>& commands = draw_command_data_;
  std::vector<std::uint32_t> instance_ids;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    GpuInstance gpu;
    gpu.model = instance.transform;
    gpu.normal_matrix = mat4(glm::transpose(glm::inverse(glm::mat3(instance.transform))));
    gpu.mesh = instance.mesh;
    gpu.material = scene.meshes[instance.mesh].material;
    instance_data_.push_back(gpu);
    const GpuMeshRange& range = mesh_range_data_[instance.mesh];
    // baseInstance selects element i of instance_ids_ for attribute 2 (divisor 1): the shader learns
    // its instance without gl_DrawID, which core 4.5 lacks.
    commands.push_back({range.index_count, 1, range.first_index, static_cast<GLint>(range.base_vertex),
                        static_cast<GLuint>(i)});
    instance_ids.push_back(static_cast<std::uint32_t>(i));
  }

  // Vertices change in place for deformable meshes (glNamedBufferSubData needs dynamic storage).
  vertices_ = create_buffer(std::span<const GpuVertex>(vertex_data_), GL_DYNAMIC_STORAGE_BIT);
  indices_ = create_buffer(std::span<const std::uint32_t>(index_data));
  mesh_ranges_ = create_buffer(std::span<const GpuMeshRange>(mesh_range_data_));
  instances_ = create_buffer(std::span<const GpuInstance>(instance_data_));
  materials_ = create_buffer(std::span<const GpuMaterial>(material_data_));
  instance_ids_ = create_buffer(std::span<const std::uint32_t>(instance_ids));
  draw_commands_ = create_buffer(std::span<const DrawElementsIndirectCommand>(commands));

  vertex_array_ = create_vertex_array();
  const GLuint vao = vertex_array_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(GpuVertex));
  glVertexArrayVertexBuffer(vao, 1, instance_ids_.id(), 0, sizeof(std::uint32_t));
  glVertexArrayBindingDivisor(vao, 1, 1);
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 4, GL_FLOAT, GL_FALSE, offsetof(GpuVertex, position_u));
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribFormat(vao, 1, 4, GL_FLOAT, GL_FALSE, offsetof(GpuVertex, normal_v));
  glVertexArrayAttribBinding(vao, 1, 0);
  glEnableVertexArrayAttrib(vao, 2);
  glVertexArrayAttribIFormat(vao, 2, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(vao, 2, 1);

  upload_textures(scene, options);
  check_gl("GPU scene upload");
}

void GpuScene::upload_textures(const Scene& scene, const GpuSceneOptions& options) {
  texture_layer_size_ = render::texture_layer_size(scene.textures, options.max_texture_layer_size);
  texture_layer_count_ = std::max<int>(1, static_cast<int>(scene.textures.size()));
  GLint max_layers = 0;
  glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &max_layers);
  if (texture_layer_count_ > max_layers)
    fail("GPU scene: {} textures exceed this GL's {} array layers", texture_layer_count_, max_layers);
  const int size = texture_layer_size_;
  const int levels = static_cast<int>(std::floor(std::log2(static_cast<float>(size)))) + 1;

  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  texture_array_ = GlTexture(id);
  glTextureStorage3D(id, levels, GL_SRGB8_ALPHA8, size, size, texture_layer_count_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (scene.textures.empty()) {
    const std::vector<std::uint8_t> white(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4, 255);
    glTextureSubImage3D(id, 0, 0, 0, 0, size, size, 1, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
  }
  for (std::size_t layer = 0; layer < scene.textures.size(); ++layer) {
    const std::vector<std::uint8_t> texels = texture_layer_texels(scene.textures[layer], size);
    glTextureSubImage3D(id, 0, 0, 0, static_cast<GLint>(layer), size, size, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                        texels.data());
  }
  glGenerateTextureMipmap(id);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_REPEAT);
  // Anisotropic filtering is core only in 4.6; 4.5 drivers offer it as an extension (grazing floors
  // blur badly without it).
  if (epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
      epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic")) {
    GLfloat max_anisotropy = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max_anisotropy);
    glTextureParameterf(id, GL_TEXTURE_MAX_ANISOTROPY_EXT, std::min(max_anisotropy, 16.0f));
  }
}

void GpuScene::update_mesh_vertices(std::uint32_t mesh, std::span<const vec3> positions,
                                    std::span<const vec3> normals) {
  if (mesh >= mesh_range_data_.size())
    fail("update_mesh_vertices: mesh {} does not exist (the scene has {})", mesh, mesh_range_data_.size());
  const GpuMeshRange& range = mesh_range_data_[mesh];
  if (positions.size() != range.vertex_count || normals.size() != range.vertex_count)
    fail("update_mesh_vertices: mesh {} has {} vertices but got {} positions and {} normals", mesh,
         range.vertex_count, positions.size(), normals.size());
  GpuVertex* first = vertex_data_.data() + range.base_vertex;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    first[i].position_u = vec4(positions[i], first[i].position_u.w);
    first[i].normal_v = vec4(normals[i], first[i].normal_v.w);
  }
  glNamedBufferSubData(vertices_.id(), static_cast<GLintptr>(range.base_vertex * sizeof(GpuVertex)),
                       static_cast<GLsizeiptr>(range.vertex_count * sizeof(GpuVertex)), first);
  ++vertex_versions_[mesh];
}

void GpuScene::bind_resources() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexBufferBinding, vertices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndexBufferBinding, indices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMeshRangeBinding, mesh_ranges_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kInstanceBinding, instances_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaterialBinding, materials_.id());
  glBindTextureUnit(kMaterialTextureUnit, texture_array_.id());
}

void GpuScene::draw_all_instances() const { draw_commands(draw_commands_.id(), 0, instance_data_.size()); }

void GpuScene::draw_commands(GLuint command_buffer, std::size_t first, std::size_t count, GLuint index_buffer) const {
  if (count == 0) return;
  bind_resources();
  if (index_buffer != 0) glVertexArrayElementBuffer(vertex_array_.id(), index_buffer);
  glBindVertexArray(vertex_array_.id());
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_buffer);
  // The offset into the bound indirect buffer travels as a pointer (GL's convention).
  const auto offset = static_cast<std::uintptr_t>(first * sizeof(DrawElementsIndirectCommand));
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(offset),
                              static_cast<GLsizei>(count), 0);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  if (index_buffer != 0) glVertexArrayElementBuffer(vertex_array_.id(), indices_.id());
}

}  // namespace glint::render
