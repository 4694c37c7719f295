#include "rt/instance_subset_tracer.h"

#include "core/error.h"

#include <algorithm>
#include <utility>

namespace glint::rt {
namespace {

constexpr std::uint32_t kNotInSubset = 0xFFFFFFFFu;

}  // namespace

std::vector<std::uint32_t> deformable_instances(const Scene& scene) {
  std::vector<std::uint32_t> instances;
  for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
    const std::uint32_t mesh = scene.instances[i].mesh;
    if (mesh < scene.meshes.size() && scene.meshes[mesh].deformable) instances.push_back(i);
  }
  return instances;
}

InstanceSubsetTracer::InstanceSubsetTracer(std::unique_ptr<RayTracer> inner, std::vector<std::uint32_t> instances)
    : inner_(std::move(inner)), instances_(std::move(instances)) {
  if (inner_ == nullptr) fail("rt instance subset: no backend to trace with");
  if (instances_.empty()) fail("rt instance subset: no instances to trace (the scene has none of the chosen kind)");
  std::vector<std::uint32_t> sorted = instances_;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    fail("rt instance subset: instance {} is listed twice", *std::adjacent_find(sorted.begin(), sorted.end()));
}

void InstanceSubsetTracer::build(const Scene& scene, const AccelOptions& options) {
  for (const std::uint32_t instance : instances_)
    if (instance >= scene.instances.size())
      fail("{}: rt instance subset: instance {} out of range ({} instances)", scene.source, instance,
           scene.instances.size());
  subset_ = Scene{};
  subset_.name = scene.name + " (subset)";
  subset_.source = scene.source;
  // The tracer needs geometry only: one plain material stands in for the scene's, and no textures.
  subset_.materials.emplace_back();
  subset_.light = scene.light;
  subset_.walkthrough = scene.walkthrough;
  subset_mesh_.assign(scene.meshes.size(), kNotInSubset);
  full_mesh_.clear();
  for (const std::uint32_t instance : instances_) {
    Instance copy = scene.instances[instance];
    std::uint32_t& mesh = subset_mesh_.at(copy.mesh);
    if (mesh == kNotInSubset) {
      mesh = static_cast<std::uint32_t>(subset_.meshes.size());
      subset_.meshes.push_back(scene.meshes[copy.mesh]);
      subset_.meshes.back().material = 0;
      full_mesh_.push_back(copy.mesh);
    }
    copy.mesh = mesh;
    subset_.instances.push_back(std::move(copy));
  }
  inner_->build(subset_, options);
}

void InstanceSubsetTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) {
  if (subset_.instances.empty()) fail("rt instance subset: update() before build()");
  if (scene.meshes.size() != subset_mesh_.size())
    fail("{}: rt instance subset: the scene has {} meshes, it was built with {}", scene.source, scene.meshes.size(),
         subset_mesh_.size());
  subset_dirty_.clear();
  for (const std::uint32_t mesh : dirty_meshes) {
    if (mesh >= scene.meshes.size())
      fail("{}: rt instance subset: dirty mesh {} out of range ({} meshes)", scene.source, mesh, scene.meshes.size());
    const std::uint32_t own = subset_mesh_[mesh];
    if (own == kNotInSubset) continue;
    subset_.meshes[own].positions = scene.meshes[mesh].positions;
    subset_.meshes[own].normals = scene.meshes[mesh].normals;
    subset_dirty_.push_back(own);
  }
  std::sort(subset_dirty_.begin(), subset_dirty_.end());  // the order backends are given (ascending)
  for (std::size_t i = 0; i < instances_.size(); ++i) subset_.instances[i].transform = scene.instances[instances_[i]].transform;
  inner_->update(subset_, subset_dirty_, policy);
}

void InstanceSubsetTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  inner_->trace_closest(rays, hits);
  for (accel::Hit& hit : hits)
    if (hit.valid()) hit.instance = instances_.at(hit.instance);
}

void InstanceSubsetTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  // Nothing to renumber: whether a ray is occluded does not say by which instance.
  inner_->trace_any(rays, occluded);
}

}  // namespace glint::rt
