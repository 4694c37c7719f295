#pragma once
// The optix backend's structure choices (docs/optix.md): its own options, which the backend registry
// lists as the backend's --accel names (backends/registry.cpp) and the backend reads from
// rt::AccelOptions::backend_structure. Modern OptiX has one builder steered by flags; glint offers its
// two meaningful settings under accel-style names, so `--accel` and accel-bench name them like every
// other structure. Header-only plain C++: known without an OptiX build (src/optix/*.cpp are compiled
// only with OptiX), so command lines are checked the same way with or without it.
#include "core/enum_names.h"

#include <string_view>

namespace glint::optix {

enum class BuildPreference {
  fast_trace,  // "optix-fasttrace": OPTIX_BUILD_FLAG_PREFER_FAST_TRACE, static GASes compacted (the default)
  fast_build,  // "optix-fastbuild": OPTIX_BUILD_FLAG_PREFER_FAST_BUILD, no compaction
};

inline constexpr EnumNames<BuildPreference, 2> kBuildPreferenceNames{
    "OptiX structure",
    {{BuildPreference::fast_trace, "optix-fasttrace"}, {BuildPreference::fast_build, "optix-fastbuild"}}};

inline constexpr auto kAllBuildPreferences = kBuildPreferenceNames.values();

// The preference rt::AccelOptions::backend_structure names; empty means the default, fast_trace.
// glint::Error listing the known names for any other name.
inline BuildPreference build_preference_of(std::string_view backend_structure) {
  return backend_structure.empty() ? BuildPreference::fast_trace : kBuildPreferenceNames.parse(backend_structure);
}

}  // namespace glint::optix
