#pragma once
// A GL buffer in host memory that the CPU reads or writes in place for the buffer's whole life:
// immutable storage mapped once, persistently and coherently (GL_MAP_PERSISTENT_BIT |
// GL_MAP_COHERENT_BIT; GL_CLIENT_STORAGE_BIT asks for host memory, since the CPU touches every
// byte each frame). Unmapped when the buffer is deleted. Shared by RayHitBuffers and
// RayTracedShadows (the CPU backends' rays, hits and occlusion flags).
#include "gl/gl_objects.h"

#include <cstddef>

namespace glint::render {

// `access`: GL_MAP_READ_BIT and/or GL_MAP_WRITE_BIT. Stores the mapping in *mapped; glint::Error
// naming `what` when the driver refuses to map it.
GlBuffer create_persistently_mapped_buffer(std::size_t bytes, GLbitfield access, void** mapped, const char* what);

}  // namespace glint::render
