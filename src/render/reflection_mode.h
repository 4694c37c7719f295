#pragma once
// Which reflections a frame gets. `off`: direct lighting only. `ssr`: screen-space reflections
// alone (failed pixels stay unreflected). The ray-traced modes (hybrid, rt) join when a ray-tracing
// backend is wired in.
#include <string_view>

namespace glint::render {

enum class ReflectionMode { off, ssr };

inline constexpr ReflectionMode kAllReflectionModes[] = {ReflectionMode::off, ReflectionMode::ssr};

std::string_view reflection_mode_name(ReflectionMode mode);
// Inverse of reflection_mode_name; an unknown name is a glint::Error listing the known ones.
ReflectionMode parse_reflection_mode(std::string_view name);

}  // namespace glint::render
