#pragma once
// glint's one error type. Every failure a user can cause (bad file, bad flag, bad value) becomes a
// glint::Error whose message names where the problem is ("scene.json: /meshes/2/file: ..." or
// "mesh.obj:12: ..."); the CLI prints that one line and exits non-zero.
#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace glint {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// Throws a glint::Error with a fmt-formatted message.
template <typename... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw Error(fmt::format(format, std::forward<Args>(args)...));
}

}  // namespace glint
