#include "rt/blas_structure.h"

#include "core/error.h"

namespace glint::rt {

std::vector<std::string> blas_structure_names() {
  std::vector<std::string> names;
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) names.emplace_back(accel::builder_name(builder));
  names.emplace_back(kKdTreeStructureName);
  return names;
}

BlasStructure parse_blas_structure(std::string_view name) {
  if (name == kKdTreeStructureName) return {BlasKind::kdtree, accel::BvhBuilder::sah};
  for (const accel::BvhBuilder builder : accel::kAllBvhBuilders)
    if (accel::builder_name(builder) == name) return {BlasKind::bvh, builder};
  std::string known;
  for (const std::string& known_name : blas_structure_names()) known += (known.empty() ? "" : ", ") + known_name;
  fail("unknown acceleration structure \"{}\" (known: {})", name, known);
}

std::string_view blas_structure_name(const BlasStructure& structure) {
  return structure.kind == BlasKind::kdtree ? kKdTreeStructureName : accel::builder_name(structure.builder);
}

bool blas_structure_refittable(const BlasStructure& structure) {
  return structure.kind == BlasKind::bvh && structure.builder != accel::BvhBuilder::sbvh;
}

}  // namespace glint::rt
