#include "render/gl_scene_deformer.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"

namespace glint::render {
namespace {

// shaders/sine_deform.comp.glsl's storage bindings (1 is the scene's vertex buffer, gpu_scene.h).
constexpr GLuint kRestBinding = 12, kIndexBinding = 13, kVertexOffsetBinding = 14, kVertexTriangleBinding = 15,
                 kPosedBinding = 16, kFaceNormalBinding = 17;
// Its uniform-buffer binding of the mesh's MeshConstants (0 is FrameConstants: the uniform-buffer
// bindings are listed beside kFrameConstantsBinding, render/frame_constants.h).
constexpr GLuint kMeshConstantsBinding = 1;
constexpr GLuint kGroupSize = 64;  // local_size_x

// The shader's MeshConstants block (std140: eight 4-byte scalars in order): what one mesh's passes
// read that never changes, written once, so a frame sets only the time and the stage.
struct MeshConstants {
  std::int32_t vertex_count = 0;
  std::int32_t triangle_count = 0;
  std::int32_t base_vertex = 0;  // the mesh's first vertex in the scene's vertex buffer
  std::int32_t displace_axis = 0;
  std::int32_t wave_axis = 0;
  float amplitude = 0.0f;
  float frequency = 0.0f;
  float speed = 0.0f;
};
static_assert(sizeof(MeshConstants) == 32);

// A storage buffer of at least one element (GL refuses empty storage).
template <typename T>
GlBuffer storage(const std::vector<T>& values) {
  if (values.empty()) return create_buffer(sizeof(T), nullptr);
  return create_buffer(std::span<const T>(values));
}

}  // namespace

GlSceneDeformer::GlSceneDeformer(const SceneDeformers& deformers, GpuScene& scene)
    : deformers_(deformers), scene_(scene), program_(ShaderProgram::from_embedded({"sine_deform.comp.glsl"})) {
  for (std::size_t k = 0; k < deformers.deformers().size(); ++k) {
    const SineDeformer& deformer = deformers.deformers()[k];
    const std::uint32_t mesh = deformers.meshes()[k];
    if (mesh >= scene.mesh_ranges().size())
      fail("GL deformer: mesh '{}' (index {}) is not in the GPU scene ({} meshes)", deformer.mesh_name(), mesh,
           scene.mesh_ranges().size());
    const GpuMeshRange& range = scene.mesh_ranges()[mesh];
    if (range.vertex_count != deformer.vertex_count())
      fail("GL deformer: mesh '{}' has {} vertices in the GPU scene but {} in its deformer", deformer.mesh_name(),
           range.vertex_count, deformer.vertex_count());
    if (deformer.vertex_offsets().back() > 0xFFFFFFFFull)
      fail("GL deformer: mesh '{}' has too many triangle corners", deformer.mesh_name());
    MeshBuffers buffers;
    buffers.vertex_count = static_cast<std::uint32_t>(deformer.vertex_count());
    buffers.triangle_count = static_cast<std::uint32_t>(deformer.indices().size() / 3);
    std::vector<vec4> rest;
    rest.reserve(deformer.rest_positions().size());
    for (const vec3& p : deformer.rest_positions()) rest.emplace_back(p, 0.0f);
    buffers.rest = storage(rest);
    buffers.indices = storage(deformer.indices());
    buffers.vertex_offsets =
        storage(std::vector<std::uint32_t>(deformer.vertex_offsets().begin(), deformer.vertex_offsets().end()));
    buffers.vertex_triangles = storage(deformer.vertex_triangles());
    buffers.posed = create_buffer(std::max<std::size_t>(rest.size(), 1) * sizeof(vec4), nullptr);
    buffers.face_normals = create_buffer(std::max<std::size_t>(buffers.triangle_count, 1) * sizeof(vec4), nullptr);
    const SineDeform& parameters = deformer.parameters();
    const MeshConstants constants{static_cast<std::int32_t>(buffers.vertex_count),
                                  static_cast<std::int32_t>(buffers.triangle_count),
                                  static_cast<std::int32_t>(range.base_vertex),
                                  parameters.displace_axis,
                                  parameters.wave_axis,
                                  parameters.amplitude,
                                  parameters.frequency,
                                  parameters.speed};
    buffers.constants = create_buffer(sizeof(constants), &constants);
    meshes_.push_back(std::move(buffers));
  }
  check_gl("GL deformer: set-up");
}

void GlSceneDeformer::apply(int frame) {
  GlPassScope scope("deform");
  const float time_seconds = deformers_.time_at(frame);
  program_.use();
  program_.set_uniform("time_seconds", time_seconds);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexBufferBinding, scene_.vertex_buffer());
  for (const MeshBuffers& mesh : meshes_) {
    if (mesh.vertex_count == 0) continue;
    glBindBufferBase(GL_UNIFORM_BUFFER, kMeshConstantsBinding, mesh.constants.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRestBinding, mesh.rest.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndexBinding, mesh.indices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexOffsetBinding, mesh.vertex_offsets.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexTriangleBinding, mesh.vertex_triangles.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPosedBinding, mesh.posed.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFaceNormalBinding, mesh.face_normals.id());
    const GLuint stages[] = {work_groups(mesh.vertex_count, kGroupSize), work_groups(mesh.triangle_count, kGroupSize),
                             work_groups(mesh.vertex_count, kGroupSize)};
    for (int stage = 0; stage < 3; ++stage) {
      if (stages[stage] == 0) continue;
      program_.set_uniform("stage", stage);
      glDispatchCompute(stages[stage], 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
  }
  // The raster passes read the vertices as vertex attributes and storage.
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl("GL deformer");
}

}  // namespace glint::render
