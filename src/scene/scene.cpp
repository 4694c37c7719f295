#include "scene/scene.h"

#include "core/error.h"
#include "core/untrusted_text.h"
#include "scene/camera_path.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <optional>

namespace glint {

Aabb Mesh::bounds() const {
  Aabb box;
  for (const vec3& p : positions) box.extend(p);
  return box;
}

std::size_t Scene::vertex_count() const {
  std::size_t total = 0;
  for (const Instance& instance : instances) total += meshes[instance.mesh].vertex_count();
  return total;
}

std::size_t Scene::triangle_count() const {
  std::size_t total = 0;
  for (const Instance& instance : instances) total += meshes[instance.mesh].triangle_count();
  return total;
}

Aabb Scene::world_bounds() const {
  Aabb box;
  for (const Instance& instance : instances) box.extend(transform_aabb(instance.transform, meshes[instance.mesh].bounds()));
  return box;
}

std::vector<std::uint32_t> Scene::deformable_meshes() const {
  std::vector<std::uint32_t> result;
  for (std::uint32_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].deformable) result.push_back(i);
  return result;
}

namespace {

// The first vertex of `mesh` (whose bounds are `box`) whose world position under `transform`
// (computed as the ray tracers' scene_geometry does, in float) is not finite, or nullopt. A mesh whose
// bounding box corners all map to finite points has none (each coordinate is affine in the position,
// largest at a corner), so the per-vertex pass runs only to find the culprit.
std::optional<std::size_t> first_non_finite_world_vertex(const Mesh& mesh, const Aabb& box, const mat4& transform) {
  bool corners_finite = true;
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    corners_finite = corners_finite && is_finite(vec3(transform * vec4(p, 1.0f)));
  }
  if (corners_finite) return std::nullopt;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (!is_finite(vec3(transform * vec4(mesh.positions[v], 1.0f)))) return v;
  return std::nullopt;
}

}  // namespace

void Scene::validate() const {
  // Only "no instances" here: counting triangles indexes meshes by the instances' mesh numbers, which are
  // checked below (an out-of-range one was read past the mesh array, ASan in the asan preset).
  if (instances.empty()) fail("{}: the scene is empty (no triangles to render)", source);
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const Mesh& mesh = meshes[m];
    const std::size_t n = mesh.positions.size();
    const auto shown_name = [&mesh] { return untrusted_text(mesh.name); };  // only when failing
    if (mesh.indices.size() % 3 != 0)
      fail("{}: mesh '{}': index count {} is not a multiple of 3", source, shown_name(), mesh.indices.size());
    if (mesh.normals.size() != n)
      fail("{}: mesh '{}': {} normals for {} positions", source, shown_name(), mesh.normals.size(), n);
    if (!mesh.uvs.empty() && mesh.uvs.size() != n)
      fail("{}: mesh '{}': {} UVs for {} positions", source, shown_name(), mesh.uvs.size(), n);
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
      if (mesh.indices[i] >= n)
        fail("{}: mesh '{}': triangle {} uses vertex {} but the mesh has {} vertices", source, shown_name(), i / 3,
             mesh.indices[i], n);
    for (std::size_t v = 0; v < n; ++v) {
      if (!is_finite(mesh.positions[v]))
        fail("{}: mesh '{}': vertex {} has a non-finite position", source, shown_name(), v);
      if (!is_finite(mesh.normals[v])) fail("{}: mesh '{}': vertex {} has a non-finite normal", source, shown_name(), v);
    }
    if (mesh.material >= materials.size())
      fail("{}: mesh '{}': material {} out of range ({} materials)", source, shown_name(), mesh.material,
           materials.size());
    if (mesh.deformable && !mesh.deform) fail("{}: mesh '{}': deformable but has no deformer", source, shown_name());
  }
  for (const Material& material : materials)
    if (material.diffuse_texture >= static_cast<int>(textures.size()))
      fail("{}: material '{}': texture {} out of range ({} textures)", source, untrusted_text(material.name),
           material.diffuse_texture, textures.size());
  std::vector<Aabb> mesh_bounds;  // once per mesh, not per instance
  mesh_bounds.reserve(meshes.size());
  for (const Mesh& mesh : meshes) mesh_bounds.push_back(mesh.bounds());
  for (const Instance& instance : instances) {
    const auto shown_name = [&instance] { return untrusted_text(instance.name); };
    if (instance.mesh >= meshes.size())
      fail("{}: instance '{}': mesh {} out of range ({} meshes)", source, shown_name(), instance.mesh, meshes.size());
    // What the acceleration structures need of each instance, checked here so that the error names the
    // scene file (the ray tracers' own checks can only say "accel: ..."), before any output is made.
    const mat4& m = instance.transform;
    if (!is_finite(m)) fail("{}: instance '{}': the transform is not finite", source, shown_name());
    // glm::inverse divides by the determinant: zero or infinite (a scale near 0 or above ~1e12 on every
    // axis) it gives a non-finite or all-zero inverse, and rays could not be taken into the instance.
    const float determinant = glm::determinant(m);
    if (determinant == 0.0f || !std::isfinite(determinant) || !is_finite(glm::inverse(m)))
      fail("{}: instance '{}': the transform cannot be inverted in float (its determinant is {})", source, shown_name(),
           determinant);
    if (const std::optional<std::size_t> v = first_non_finite_world_vertex(meshes[instance.mesh], mesh_bounds[instance.mesh], m))
      fail("{}: instance '{}': vertex {} of mesh '{}' is not finite after the instance transform (the transform "
           "scales or moves it beyond float range)",
           source, shown_name(), *v, untrusted_text(meshes[instance.mesh].name));
  }
  if (triangle_count() == 0) fail("{}: the scene is empty (no triangles to render)", source);
  try {
    const WalkthroughAnimation paths(*this);  // checks the camera and light paths can be animated
  } catch (const Error& e) {
    fail("{}: {}", source, e.what());
  }
}

}  // namespace glint
