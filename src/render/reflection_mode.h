#pragma once
// Which reflections a frame gets:
//   off:    direct lighting only;
//   ssr:    screen-space reflections alone (failed pixels stay unreflected);
//   hybrid: SSR, then a ray traced for every pixel SSR failed on (the paper's method);
//   rt:     a ray traced for every reflective pixel (the paper's pure ray-tracing solution, glint's
//           reference image).
#include "core/enum_names.h"

#include <string_view>

namespace glint::render {

enum class ReflectionMode { off, ssr, hybrid, rt };

inline constexpr EnumNames<ReflectionMode, 4> kReflectionModeNames{
    "reflection mode",
    {{ReflectionMode::off, "off"}, {ReflectionMode::ssr, "ssr"}, {ReflectionMode::hybrid, "hybrid"},
     {ReflectionMode::rt, "rt"}}};

inline constexpr auto kAllReflectionModes = kReflectionModeNames.values();

inline std::string_view reflection_mode_name(ReflectionMode mode) { return kReflectionModeNames.name_of(mode); }
// Inverse of reflection_mode_name; an unknown name is a glint::Error listing the known ones.
inline ReflectionMode parse_reflection_mode(std::string_view name) { return kReflectionModeNames.parse(name); }

bool uses_ssr(ReflectionMode mode);          // ssr, hybrid
bool uses_ray_tracing(ReflectionMode mode);  // hybrid, rt

}  // namespace glint::render
