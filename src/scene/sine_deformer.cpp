#include "scene/sine_deformer.h"

#include "scene/sine_deform_math.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

namespace glint {
namespace {

// Vertices (or triangles) per TBB task: small meshes run as one task, so they pay no scheduling cost.
constexpr std::size_t kGrain = 4096;

template <typename Body>
void parallel_range(std::size_t count, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) body(i);
  });
}

}  // namespace

SineDeformer::SineDeformer(const Mesh& rest_mesh, SineDeform parameters)
    : mesh_name_(rest_mesh.name), parameters_(parameters), rest_positions_(rest_mesh.positions),
      indices_(rest_mesh.indices) {
  const SineDeform& p = parameters_;
  if (p.displace_axis < 0 || p.displace_axis > 2)
    fail("mesh '{}': sine deform displace_axis must be 0, 1 or 2, got {}", mesh_name_, p.displace_axis);
  if (p.wave_axis < 0 || p.wave_axis > 2)
    fail("mesh '{}': sine deform wave_axis must be 0, 1 or 2, got {}", mesh_name_, p.wave_axis);
  if (!std::isfinite(p.amplitude) || !std::isfinite(p.frequency) || !std::isfinite(p.speed))
    fail("mesh '{}': sine deform amplitude, frequency and speed must be finite", mesh_name_);
  if (indices_.size() % 3 != 0)
    fail("mesh '{}': {} indices is not a whole number of triangles", mesh_name_, indices_.size());
  const std::size_t vertex_count = rest_positions_.size();
  for (std::size_t i = 0; i < indices_.size(); ++i)
    if (indices_[i] >= vertex_count)
      fail("mesh '{}': index {} is {}, past the {} vertices", mesh_name_, i, indices_[i], vertex_count);

  // Counting sort of (vertex, triangle) pairs by vertex; triangles are visited in ascending order,
  // so each vertex's list comes out ascending.
  vertex_offsets_.assign(vertex_count + 1, 0);
  for (const std::uint32_t v : indices_) ++vertex_offsets_[v + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) vertex_offsets_[v + 1] += vertex_offsets_[v];
  vertex_triangles_.resize(indices_.size());
  std::vector<std::size_t> cursor(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
  for (std::size_t corner = 0; corner < indices_.size(); ++corner)
    vertex_triangles_[cursor[indices_[corner]]++] = static_cast<std::uint32_t>(corner / 3);
  face_normals_.resize(indices_.size() / 3);
}

void SineDeformer::apply(Mesh& mesh, float time_seconds) {
  if (mesh.positions.size() != rest_positions_.size())
    fail("mesh '{}': the sine deformer was built for {} vertices, the mesh has {}", mesh_name_,
         rest_positions_.size(), mesh.positions.size());
  if (mesh.indices.size() != indices_.size())
    fail("mesh '{}': the sine deformer was built for {} triangles, the mesh has {}", mesh_name_,
         indices_.size() / 3, mesh.indices.size() / 3);

  const float phase = parameters_.speed * time_seconds;
  parallel_range(rest_positions_.size(),
                 [&](std::size_t v) { mesh.positions[v] = sine_displaced(rest_positions_[v], parameters_, phase); });

  // Smooth normals as compute_smooth_normals makes them (area-weighted face sum, +y where it
  // vanishes), but gathered per vertex so both loops run in parallel without races.
  std::vector<vec3>& face_normals = face_normals_;
  parallel_range(face_normals.size(), [&](std::size_t t) {
    const vec3 a = mesh.positions[indices_[3 * t]], b = mesh.positions[indices_[3 * t + 1]],
               c = mesh.positions[indices_[3 * t + 2]];
    face_normals[t] = weighted_face_normal(a, b, c);
  });
  mesh.normals.resize(rest_positions_.size());
  parallel_range(rest_positions_.size(), [&](std::size_t v) {
    vec3 sum(0.0f);
    for (std::size_t k = vertex_offsets_[v]; k < vertex_offsets_[v + 1]; ++k) sum += face_normals[vertex_triangles_[k]];
    mesh.normals[v] = smooth_normal_from_sum(sum);
  });
}

SceneDeformers::SceneDeformers(const Scene& scene)
    : scene_mesh_count_(scene.meshes.size()), frames_per_second_(scene.walkthrough.frames_per_second) {
  if (!(frames_per_second_ > 0.0f) || !std::isfinite(frames_per_second_))
    fail("{}: walkthrough frames_per_second must be a finite number > 0, got {}", scene.source, frames_per_second_);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (!mesh.deformable || !mesh.deform) continue;
    deformers_.emplace_back(mesh, *mesh.deform);
    mesh_indices_.push_back(static_cast<std::uint32_t>(m));
  }
}

float SceneDeformers::time_at(int frame) const {
  if (frame < 0) fail("deformers: frame must be >= 0, got {}", frame);
  // The same conversion as WalkthroughAnimation::at, so geometry and FrameState agree on the time.
  return static_cast<float>(double(frame) / double(frames_per_second_));
}

std::vector<std::uint32_t> SceneDeformers::apply(Scene& scene, int frame) {
  if (frame < 0) fail("deformers: frame must be >= 0, got {}", frame);
  if (scene.meshes.size() != scene_mesh_count_)
    fail("deformers: built for a scene with {} meshes, given one with {}", scene_mesh_count_, scene.meshes.size());
  const float time_seconds = time_at(frame);
  for (std::size_t k = 0; k < deformers_.size(); ++k) deformers_[k].apply(scene.meshes[mesh_indices_[k]], time_seconds);
  return mesh_indices_;
}

}  // namespace glint
