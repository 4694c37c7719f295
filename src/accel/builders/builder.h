#pragma once
// Picking a builder by name, for callers (CLI, benchmarks, tests) that iterate over the menu.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"
#include "core/enum_names.h"

#include <span>
#include <string_view>

namespace glint::accel {

enum class BvhBuilder { none, median, sah, sbvh, lbvh, trbvh, ploc };

inline constexpr EnumNames<BvhBuilder, 7> kBvhBuilderNames{
    "BVH builder",
    {{BvhBuilder::none, "none"}, {BvhBuilder::median, "median"}, {BvhBuilder::sah, "sah"}, {BvhBuilder::sbvh, "sbvh"},
     {BvhBuilder::lbvh, "lbvh"}, {BvhBuilder::trbvh, "trbvh"}, {BvhBuilder::ploc, "ploc"}}};

inline constexpr auto kAllBvhBuilders = kBvhBuilderNames.values();

inline std::string_view builder_name(BvhBuilder builder) { return kBvhBuilderNames.name_of(builder); }
// Inverse of builder_name; glint::Error listing the known names otherwise.
inline BvhBuilder parse_bvh_builder(std::string_view name) { return kBvhBuilderNames.parse(name); }

// sbvh from boxes alone clips references as boxes (no triangle geometry to clip).
Bvh build_bvh(BvhBuilder builder, const BuildInput& input, const BuildOptions& options = {});
// Convenience for a BLAS: bounds the triangles first (that time is included in build_ms); sbvh
// clips the triangles themselves.
Bvh build_bvh(BvhBuilder builder, const TriangleMesh& mesh, const BuildOptions& options = {});

// The builders keep the large blocks they and freed Bvhs released (up to 256 MiB, parallel_array.h)
// for the next build, which then pays no page faults for them: a per-frame rebuild reuses the last
// frame's memory. This gives those blocks back to the system, e.g. once a scene is loaded.
void release_build_memory();

}  // namespace glint::accel
