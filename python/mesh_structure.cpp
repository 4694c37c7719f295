#include "python/mesh_structure.h"

#include "backends/registry.h"
#include "core/error.h"
#include "rt/blas_structure.h"

#include <fmt/ranges.h>

#include <algorithm>
#include <iterator>
#include <utility>

namespace glint::python {
namespace {

constexpr const char* kSource = "glint.Structure";

// The scene around the mesh. The tracers take a whole Scene (Scene::validate checks it: indices in
// range, finite vertices, a walkthrough that can be animated), so the mesh gets what a scene needs
// and the tracers ignore: unused normals, one material, a fixed camera. It is deformable, because
// its vertices may move (refit): backends build such meshes' structures to be updated.
Scene one_mesh_scene(std::vector<vec3> positions, std::vector<uint32_t> indices) {
  Scene scene;
  scene.name = "structure";
  scene.source = kSource;
  Mesh mesh;
  mesh.name = "vertices";
  mesh.normals.assign(positions.size(), vec3(0.0f, 0.0f, 1.0f));
  mesh.positions = std::move(positions);
  mesh.indices = std::move(indices);
  mesh.deformable = true;
  mesh.deform = SineDeform{};  // never applied: the caller moves the vertices
  scene.meshes.push_back(std::move(mesh));
  scene.materials.emplace_back();
  scene.instances.push_back(Instance{"mesh", 0, mat4(1.0f)});
  scene.walkthrough.camera = CameraPathSpec::fixed(vec3(0.0f, 0.0f, 1.0f), vec3(0.0f));
  return scene;
}

}  // namespace

MeshStructure::MeshStructure(std::vector<vec3> positions, std::vector<uint32_t> indices, const std::string& builder,
                             const std::string& backend)
    : builder_(builder), backend_(backend), scene_(one_mesh_scene(std::move(positions), std::move(indices))) {
  if (std::find(std::begin(kStructureBackends), std::end(kStructureBackends), backend) == std::end(kStructureBackends))
    fail("{}: unknown backend \"{}\" (known: {})", kSource, backend, fmt::join(kStructureBackends, ", "));
  rt::AccelOptions options;
  const rt::BlasStructure structure = rt::parse_blas_structure(builder);
  options.set_structure(structure);
  if (!backends::find_backend(backend).takes_glint_builders && rt::blas_structure_name(structure) != "sah")
    fail("{}: builder=\"{}\" applies to the cpu and cuda backends; the {} backend builds its own structures",
         kSource, builder, backend);
  scene_.validate();
  backends::check_backend_runnable(backend, fmt::format("{}(backend=\"{}\")", kSource, backend));
  tracer_ = backends::make_ray_tracer(backend);
  tracer_->build(scene_, options);
}

void MeshStructure::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  tracer_->trace_closest(rays, hits);
}

void MeshStructure::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  tracer_->trace_any(rays, occluded);
}

void MeshStructure::update(std::vector<vec3> positions, rt::UpdatePolicy policy) {
  Mesh& mesh = scene_.meshes[0];
  if (positions.size() != mesh.positions.size())
    fail("{}: refit needs the same number of vertices as the structure was built with ({}), got {}", kSource,
         mesh.positions.size(), positions.size());
  std::vector<vec3> previous = std::exchange(mesh.positions, std::move(positions));
  try {
    scene_.validate();  // non-finite vertices, named, before the tracer sees them
    const uint32_t dirty[] = {0};
    tracer_->update(scene_, dirty, policy);
  } catch (const Error&) {
    mesh.positions = std::move(previous);  // the scene keeps describing what the structure holds
    throw;
  }
}

}  // namespace glint::python
