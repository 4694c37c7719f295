#include "render/persistent_buffer.h"

#include "core/error.h"

namespace glint::render {

GlBuffer create_persistently_mapped_buffer(std::size_t bytes, GLbitfield access, void** mapped, const char* what) {
  constexpr GLbitfield kPersistent = GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  GlBuffer buffer = create_buffer(bytes, nullptr, access | kPersistent | GL_CLIENT_STORAGE_BIT);
  *mapped = glMapNamedBufferRange(buffer.id(), 0, static_cast<GLsizeiptr>(bytes), access | kPersistent);
  if (*mapped == nullptr) fail("{}: could not map the buffer ({} bytes) persistently", what, bytes);
  return buffer;
}

}  // namespace glint::render
