#pragma once
// The OptiX device programs compiled at build time (src/optix/device/*.cu -> OptiX-IR) and
// embedded into the binary by cmake/GlintEmbedOptixModules.cmake, so glint runs without its source
// tree or nvcc.
#include <cstddef>
#include <span>
#include <string_view>

namespace glint::optix {

struct EmbeddedOptixModule {
  const char* name;  // the .cu file's name without extension
  const unsigned char* bytes;
  std::size_t size;
};

// Defined in the generated embedded_optix_modules.cpp.
extern const EmbeddedOptixModule kEmbeddedOptixModules[];
extern const std::size_t kEmbeddedOptixModuleCount;

// The module compiled from src/optix/device/<name>.cu; glint::Error naming the embedded ones otherwise.
std::span<const unsigned char> embedded_optix_module(std::string_view name);

}  // namespace glint::optix
