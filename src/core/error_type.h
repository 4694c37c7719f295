#pragma once
// glint::Error alone, without fmt: for headers that .cu files include (nvcc cannot compile fmt), such
// as core/enum_names.h. Everything else includes core/error.h, which adds fail().
#include <stdexcept>
#include <string>

namespace glint {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace glint
