#pragma once
// The per-mesh structure (BLAS) of the backends that build glint's own structures (cpu, cuda): a
// BVH from one of accel's builders, or the SAH kd-tree (accel/kdtree/kdtree.h), which the paper compares
// beside them. One menu of names for every place that takes a structure (--accel, bench's --accels,
// the viewer): the builder names, then "kdtree".
#include "accel/builders/builder.h"

#include <string>
#include <string_view>
#include <vector>

namespace glint::rt {

enum class BlasKind { bvh, kdtree };

inline constexpr std::string_view kKdTreeStructureName = "kdtree";

struct BlasStructure {
  BlasKind kind = BlasKind::bvh;
  accel::BvhBuilder builder = accel::BvhBuilder::sah;  // kind bvh only
};

// accel::builder_name of each builder in kAllBvhBuilders' order, then "kdtree".
std::vector<std::string> blas_structure_names();
// "kdtree" or a builder name; glint::Error listing blas_structure_names() otherwise.
BlasStructure parse_blas_structure(std::string_view name);
std::string_view blas_structure_name(const BlasStructure& structure);
// Whether an update can refit it: not sbvh (leaves hold clipped references) nor the kd-tree (a
// triangle is referenced by every cell it crosses; moved vertices change which cells those are).
bool blas_structure_refittable(const BlasStructure& structure);

}  // namespace glint::rt
