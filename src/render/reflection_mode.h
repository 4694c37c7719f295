#pragma once
// Which reflections a frame gets:
//   off:    direct lighting only;
//   ssr:    screen-space reflections alone (failed pixels stay unreflected);
//   hybrid: SSR, then a ray traced for every pixel SSR failed on (the paper's method);
//   rt:     a ray traced for every reflective pixel (the paper's pure ray-tracing solution, glint's
//           reference image).
#include <string_view>

namespace glint::render {

enum class ReflectionMode { off, ssr, hybrid, rt };

inline constexpr ReflectionMode kAllReflectionModes[] = {ReflectionMode::off, ReflectionMode::ssr,
                                                         ReflectionMode::hybrid, ReflectionMode::rt};

std::string_view reflection_mode_name(ReflectionMode mode);
// Inverse of reflection_mode_name; an unknown name is a glint::Error listing the known ones.
ReflectionMode parse_reflection_mode(std::string_view name);

bool uses_ssr(ReflectionMode mode);          // ssr, hybrid
bool uses_ray_tracing(ReflectionMode mode);  // hybrid, rt

}  // namespace glint::render
