#include "gl/gpu_memory.h"

#include <epoxy/gl.h>

namespace glint {
namespace {

// From GL_NVX_gpu_memory_info (not in every epoxy header); values are in KiB.
constexpr GLenum kTotalAvailableMemoryNvx = 0x9048;
constexpr GLenum kCurrentAvailableMemoryNvx = 0x9049;

}  // namespace

std::optional<std::uint64_t> gpu_memory_used_bytes() {
  static const bool supported = epoxy_has_gl_extension("GL_NVX_gpu_memory_info");
  if (!supported) return std::nullopt;
  GLint total_kib = 0, available_kib = 0;
  glGetIntegerv(kTotalAvailableMemoryNvx, &total_kib);
  glGetIntegerv(kCurrentAvailableMemoryNvx, &available_kib);
  if (total_kib <= 0 || available_kib < 0 || available_kib > total_kib) return std::nullopt;
  return static_cast<std::uint64_t>(total_kib - available_kib) * 1024u;
}

}  // namespace glint
