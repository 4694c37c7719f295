#include "render/gl_scene_deformer.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

#include <algorithm>
#include <cstddef>

namespace glint::render {
namespace {

// shaders/sine_deform.comp.glsl's storage bindings (1 is the scene's vertex buffer, gpu_scene.h).
constexpr GLuint kRestBinding = 12, kIndexBinding = 13, kVertexOffsetBinding = 14, kVertexTriangleBinding = 15,
                 kPosedBinding = 16, kFaceNormalBinding = 17, kJobBinding = 18;
// write_positions_to()'s buffer: above the renderer's passes' bindings (0..19), below the gl
// backend's (21..29), which a pass's dispatch leaves as they are.
constexpr GLuint kTargetBinding = 20;
constexpr std::uint32_t kNoTarget = 0xFFFFFFFF;  // DeformJob::target_vertex of a job not written out
constexpr GLuint kGroupSize = 64;                // local_size_x
constexpr std::uint64_t kMaxIndex = 0xFFFFFFFF;  // the shader indexes and counts invocations in uint

// The shader's DeformJob (std430: twelve 4-byte scalars in order): one mesh's place in the dispatches
// and the concatenated arrays, and its deformation; written once, so a frame sets only the time.
struct DeformJob {
  std::uint32_t first_invocation = 0;  // in the pose stage
  std::uint32_t first_vertex = 0;      // in rest, posed and vertex_offsets; the normals stage's first invocation
  std::uint32_t first_triangle = 0;    // in face_normals
  std::uint32_t vertex_count = 0;
  std::uint32_t triangle_count = 0;
  std::uint32_t base_vertex = 0;  // the mesh's first vertex in the scene's vertex buffer
  std::int32_t displace_axis = 0;
  std::int32_t wave_axis = 0;
  float amplitude = 0.0f;
  float frequency = 0.0f;
  float speed = 0.0f;
  std::uint32_t target_vertex = kNoTarget;  // its first vertex in write_positions_to()'s buffer
};
static_assert(sizeof(DeformJob) == 48);

}  // namespace

GlSceneDeformer::GlSceneDeformer(const SceneDeformers& deformers, GpuScene& scene)
    : deformers_(deformers), scene_(scene), program_(ShaderProgram::from_embedded({"sine_deform.comp.glsl"})) {
  // The meshes one after the other, their indices rebased into the concatenation, so the shader adds
  // no per-mesh offset to what it reads.
  std::vector<vec4> rest;
  std::vector<std::uint32_t> indices, vertex_offsets, vertex_triangles;
  std::vector<DeformJob> jobs;
  std::uint64_t vertices = 0, triangles = 0, corners = 0, invocations = 0;
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
    const std::uint64_t vertex_count = deformer.vertex_count(), triangle_count = deformer.indices().size() / 3;
    // No job without vertices: the search needs every job's first invocation distinct.
    job_of_mesh_.push_back(vertex_count == 0 ? -1 : static_cast<std::int32_t>(jobs.size()));
    if (vertex_count == 0) continue;
    const SineDeform& parameters = deformer.parameters();
    jobs.push_back({static_cast<std::uint32_t>(invocations), static_cast<std::uint32_t>(vertices),
                    static_cast<std::uint32_t>(triangles), static_cast<std::uint32_t>(vertex_count),
                    static_cast<std::uint32_t>(triangle_count), range.base_vertex, parameters.displace_axis,
                    parameters.wave_axis, parameters.amplitude, parameters.frequency, parameters.speed, kNoTarget});
    for (const vec3& p : deformer.rest_positions()) rest.emplace_back(p, 0.0f);
    for (const std::uint32_t index : deformer.indices()) indices.push_back(static_cast<std::uint32_t>(vertices + index));
    // Each mesh's final offset is the next mesh's first: one closing entry after the loop.
    for (std::size_t v = 0; v < vertex_count; ++v)
      vertex_offsets.push_back(static_cast<std::uint32_t>(corners + deformer.vertex_offsets()[v]));
    for (const std::uint32_t triangle : deformer.vertex_triangles())
      vertex_triangles.push_back(static_cast<std::uint32_t>(triangles + triangle));
    vertices += vertex_count;
    triangles += triangle_count;
    corners += deformer.vertex_offsets().back();
    invocations += std::max(vertex_count, triangle_count);
  }
  vertex_offsets.push_back(static_cast<std::uint32_t>(corners));
  // Corners are 3 per triangle, so this bounds indices[3t + 2] too.
  if (std::max({vertices, corners, invocations}) > kMaxIndex)
    fail("GL deformer: the deformable meshes have {} vertices, {} triangle corners and {} pose invocations, more "
         "than 32-bit indices count",
         vertices, corners, invocations);
  rest_ = create_nonempty_buffer(std::span<const vec4>(rest));
  indices_ = create_nonempty_buffer(std::span<const std::uint32_t>(indices));
  vertex_offsets_ = create_nonempty_buffer(std::span<const std::uint32_t>(vertex_offsets));
  vertex_triangles_ = create_nonempty_buffer(std::span<const std::uint32_t>(vertex_triangles));
  posed_ = create_buffer(std::max<std::uint64_t>(vertices, 1) * sizeof(vec4), nullptr);
  face_normals_ = create_buffer(std::max<std::uint64_t>(triangles, 1) * sizeof(vec4), nullptr);
  jobs_ = create_nonempty_buffer(std::span<const DeformJob>(jobs), GL_DYNAMIC_STORAGE_BIT);
  target_first_vertex_.assign(jobs.size(), kNoTarget);
  job_count_ = static_cast<std::uint32_t>(jobs.size());
  pose_invocations_ = static_cast<std::uint32_t>(invocations);
  vertex_count_ = static_cast<std::uint32_t>(vertices);
  // Grids of up to 65,535 x 65,535 work groups (one dimension alone stops at 4.2 million vertices).
  pose_grid_ = grid_of_work_groups(pose_invocations_, kGroupSize, "GL deformer: pose stage");
  normals_grid_ = grid_of_work_groups(vertex_count_, kGroupSize, "GL deformer: normals stage");
  glProgramUniform1ui(program_.id(), program_.uniform_location("job_count"), job_count_);
  time_location_ = program_.uniform_location("time_seconds");
  stage_location_ = program_.uniform_location("stage");
  invocation_count_location_ = program_.uniform_location("invocation_count");
  check_gl("GL deformer: set-up");
}

void GlSceneDeformer::write_positions_to(GLuint buffer, std::span<const std::uint32_t> first_vertex) {
  if (first_vertex.size() != job_of_mesh_.size())
    fail("GL deformer: {} first vertices for the positions' copies, one per deforming mesh ({}) expected",
         first_vertex.size(), job_of_mesh_.size());
  target_buffer_ = buffer;
  for (std::size_t k = 0; k < first_vertex.size(); ++k) {
    const std::int32_t job = job_of_mesh_[k];
    if (job < 0 || target_first_vertex_[job] == first_vertex[k]) continue;
    target_first_vertex_[job] = first_vertex[k];
    glNamedBufferSubData(jobs_.id(), static_cast<GLintptr>(job * sizeof(DeformJob) + offsetof(DeformJob, target_vertex)),
                         sizeof(std::uint32_t), &first_vertex[k]);
  }
  check_gl("GL deformer: positions' target");
}

void GlSceneDeformer::apply(int frame) {
  GlPassScope scope("deform");
  if (job_count_ > 0) {
    glProgramUniform1f(program_.id(), time_location_, deformers_.time_at(frame));
    program_.use();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexBufferBinding, scene_.vertex_buffer());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kRestBinding, rest_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kIndexBinding, indices_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexOffsetBinding, vertex_offsets_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kVertexTriangleBinding, vertex_triangles_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPosedBinding, posed_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFaceNormalBinding, face_normals_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kJobBinding, jobs_.id());
    // Without a target no job writes there; something is bound all the same.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTargetBinding, target_buffer_ != 0 ? target_buffer_ : posed_.id());
    // Pose: every vertex's position and every triangle's normal.
    glProgramUniform1i(program_.id(), stage_location_, 0);
    glProgramUniform1ui(program_.id(), invocation_count_location_, pose_invocations_);
    glDispatchCompute(pose_grid_.columns, pose_grid_.rows, 1);
    // The normals stage reads the posed positions and every triangle's normal around a vertex.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glProgramUniform1i(program_.id(), stage_location_, 1);
    glProgramUniform1ui(program_.id(), invocation_count_location_, vertex_count_);
    glDispatchCompute(normals_grid_.columns, normals_grid_.rows, 1);
  }
  // The raster passes read the vertices as vertex attributes and storage.
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  check_gl("GL deformer");
}

}  // namespace glint::render
