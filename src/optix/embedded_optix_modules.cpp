#include "optix/embedded_optix_modules.h"

#include "core/error.h"

#include <string>

namespace glint::optix {

std::span<const unsigned char> embedded_optix_module(std::string_view name) {
  std::string known;
  for (std::size_t i = 0; i < kEmbeddedOptixModuleCount; ++i) {
    const EmbeddedOptixModule& module = kEmbeddedOptixModules[i];
    if (name == module.name) return {module.bytes, module.size};
    known += known.empty() ? "" : ", ";
    known += module.name;
  }
  fail("no embedded OptiX module \"{}\" (embedded: {})", name, known);
}

}  // namespace glint::optix
