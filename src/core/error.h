#pragma once
// glint's one error type. Every failure a user can cause (bad file, bad flag, bad value) becomes a
// glint::Error whose message names where the problem is ("scene.json: /meshes/2/file: ..." or
// "mesh.obj:12: ..."); the CLI prints that one line and exits non-zero.
#include "core/error_type.h"

#include <fmt/format.h>

#include <string>

namespace glint {

// Throws a glint::Error with a fmt-formatted message.
template <typename... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw Error(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace glint
