#pragma once
// Move-only owners of GL object names (buffers, textures, framebuffers, vertex arrays, queries,
// shaders, programs), created with the GL 4.5 direct-state-access calls so that making an object
// never disturbs the current bindings. An owner deletes its object when it dies; it must die while
// the context that created it is current (so keep GL objects inside the HeadlessGlContext's life).
#include "core/error.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <span>
#include <utility>

namespace glint {

template <typename Traits>
class GlObject {
public:
  GlObject() = default;                        // owns nothing (id 0)
  explicit GlObject(GLuint id) : id_(id) {}    // takes ownership of an existing name
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) Traits::destroy(std::exchange(id_, 0));
  }

private:
  GLuint id_ = 0;
};

namespace gl_traits {
struct Buffer { static void destroy(GLuint id) { glDeleteBuffers(1, &id); } };
struct Texture { static void destroy(GLuint id) { glDeleteTextures(1, &id); } };
struct Framebuffer { static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); } };
struct VertexArray { static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); } };
struct Query { static void destroy(GLuint id) { glDeleteQueries(1, &id); } };
struct Shader { static void destroy(GLuint id) { glDeleteShader(id); } };
struct Program { static void destroy(GLuint id) { glDeleteProgram(id); } };
}  // namespace gl_traits

using GlBuffer = GlObject<gl_traits::Buffer>;
using GlTexture = GlObject<gl_traits::Texture>;
using GlFramebuffer = GlObject<gl_traits::Framebuffer>;
using GlVertexArray = GlObject<gl_traits::VertexArray>;
using GlQuery = GlObject<gl_traits::Query>;
using GlShader = GlObject<gl_traits::Shader>;
using GlProgram = GlObject<gl_traits::Program>;

// An immutable-storage buffer of `bytes` bytes (glNamedBufferStorage); `data` may be null.
// `flags` are the storage flags, e.g. GL_DYNAMIC_STORAGE_BIT to allow glNamedBufferSubData.
inline GlBuffer create_buffer(std::size_t bytes, const void* data, GLbitfield flags = 0) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  GlBuffer buffer(id);
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), data, flags);
  return buffer;
}

template <typename T>
GlBuffer create_buffer(std::span<const T> data, GLbitfield flags = 0) {
  return create_buffer(data.size_bytes(), data.data(), flags);
}

// A buffer of `data`, or of one value-initialised T where `data` is empty: GL refuses empty storage,
// and a pass over nothing still binds a buffer.
template <typename T>
GlBuffer create_nonempty_buffer(std::span<const T> data, GLbitfield flags = 0) {
  if (!data.empty()) return create_buffer(data, flags);
  const T filler{};
  return create_buffer(sizeof(T), &filler, flags);
}

// A 2D texture with immutable storage for `levels` mip levels (glTextureStorage2D).
inline GlTexture create_texture_2d(GLenum internal_format, int width, int height, int levels = 1) {
  if (width <= 0 || height <= 0 || levels <= 0)
    fail("create_texture_2d: invalid size {}x{} with {} levels", width, height, levels);
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  GlTexture texture(id);
  glTextureStorage2D(id, levels, internal_format, width, height);
  return texture;
}

// A cube map (six square faces of `size` pixels) with immutable storage, e.g. for point-light shadows.
inline GlTexture create_texture_cube(GLenum internal_format, int size, int levels = 1) {
  if (size <= 0 || levels <= 0) fail("create_texture_cube: invalid size {} with {} levels", size, levels);
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
  GlTexture texture(id);
  glTextureStorage2D(id, levels, internal_format, size, size);
  return texture;
}

inline GlFramebuffer create_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return GlFramebuffer(id);
}

inline GlVertexArray create_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return GlVertexArray(id);
}

// A query object of a fixed target (GL_TIME_ELAPSED, GL_SAMPLES_PASSED, ...).
inline GlQuery create_query(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return GlQuery(id);
}

// Throws a glint::Error naming `what` and the status when the framebuffer cannot be rendered to.
inline void require_framebuffer_complete(const GlFramebuffer& framebuffer, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return;
  const char* name = "unknown status";
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED: name = "GL_FRAMEBUFFER_UNDEFINED"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: name = "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: name = "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: name = "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: name = "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER"; break;
    case GL_FRAMEBUFFER_UNSUPPORTED: name = "GL_FRAMEBUFFER_UNSUPPORTED"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: name = "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE"; break;
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS: name = "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS"; break;
    default: break;
  }
  fail("{}: framebuffer is not complete ({}, {:#06x})", what, name, status);
}

}  // namespace glint
