#pragma once
// `count` elements of type T from element `first` of a GL buffer, read back on the host (which waits
// for the GPU): how the GL tests look at what a pass or a tracer wrote.
#include <epoxy/gl.h>

#include <cstddef>
#include <vector>

namespace glint::testing {

template <typename T>
std::vector<T> read_buffer(GLuint buffer, std::size_t first, std::size_t count) {
  std::vector<T> data(count);
  glGetNamedBufferSubData(buffer, static_cast<GLintptr>(first * sizeof(T)), static_cast<GLsizeiptr>(count * sizeof(T)),
                          data.data());
  return data;
}

}  // namespace glint::testing
