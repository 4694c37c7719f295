#pragma once
// The optix backend's builder choices (docs/optix.md). Modern OptiX has one builder steered by
// flags; glint offers its two meaningful settings under accel-style names, so `--accel` and
// accel-bench name them like every other structure. Plain C++: known without an OptiX build, so
// command lines are checked the same way with or without it.
#include <string_view>

namespace glint::rt {

enum class OptixBuildPreference {
  fast_trace,  // "optix-fasttrace": OPTIX_BUILD_FLAG_PREFER_FAST_TRACE, static GASes compacted
  fast_build,  // "optix-fastbuild": OPTIX_BUILD_FLAG_PREFER_FAST_BUILD, no compaction
};

inline constexpr OptixBuildPreference kAllOptixBuildPreferences[] = {OptixBuildPreference::fast_trace,
                                                                     OptixBuildPreference::fast_build};

// "optix-fasttrace" or "optix-fastbuild".
std::string_view optix_accel_name(OptixBuildPreference preference);
// True for the names optix_accel_name returns.
bool is_optix_accel_name(std::string_view name);
// Inverse of optix_accel_name; glint::Error listing the known names otherwise.
OptixBuildPreference parse_optix_accel(std::string_view name);

}  // namespace glint::rt
