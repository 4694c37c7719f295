#pragma once
// Which reflections a frame gets:
//   off:    direct lighting only;
//   ssr:    screen-space reflections alone (failed pixels stay unreflected);
//   hybrid: SSR, then a ray traced for every pixel SSR failed on (the paper's method);
//   rt:     a ray traced for every reflective pixel (the paper's pure ray-tracing solution, glint's
//           reference image);
//   auto:   per 8x8 tile and frame one of ssr only, SSR with a traced fallback, or rays only, chosen
//           from the tile's reprojected SSR failure rate, a measured cost model and a ray budget
//           (render/adaptive_reflections.h, docs/hybrid.md "auto"). The enumerator is `adaptive`
//           (`auto` is a C++ keyword); its name is "auto".
#include "core/enum_names.h"

#include <string_view>

namespace glint::render {

enum class ReflectionMode { off, ssr, hybrid, rt, adaptive };

inline constexpr EnumNames<ReflectionMode, 5> kReflectionModeNames{
    "reflection mode",
    {{ReflectionMode::off, "off"}, {ReflectionMode::ssr, "ssr"}, {ReflectionMode::hybrid, "hybrid"},
     {ReflectionMode::rt, "rt"}, {ReflectionMode::adaptive, "auto"}}};

inline constexpr auto kAllReflectionModes = kReflectionModeNames.values();

inline std::string_view reflection_mode_name(ReflectionMode mode) { return kReflectionModeNames.name_of(mode); }
// Inverse of reflection_mode_name; an unknown name is a glint::Error listing the known ones.
inline ReflectionMode parse_reflection_mode(std::string_view name) { return kReflectionModeNames.parse(name); }

bool uses_ssr(ReflectionMode mode);          // ssr, hybrid, auto
bool uses_ray_tracing(ReflectionMode mode);  // hybrid, rt, auto

}  // namespace glint::render
