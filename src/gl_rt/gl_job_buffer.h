#pragma once
// The job list of one of the gl backend's compute dispatches over BLAS regions (the GPU refit's, the
// SAH cost's): a small GL storage buffer of uvec4s that the host rewrites only when the list changed,
// so a frame that refits or measures the same meshes as the last one uploads nothing. Grown as needed.
#include "gl/gl_objects.h"

#include <glm/vec4.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace glint::gl_rt {

class GlJobBuffer {
public:
  // Makes the buffer hold `jobs` (at least one) and returns its name; needs the GL context current.
  GLuint hold(std::span<const glm::uvec4> jobs);

private:
  GlBuffer buffer_;
  std::size_t capacity_ = 0;
  std::vector<glm::uvec4> held_;  // what buffer_ holds
};

}  // namespace glint::gl_rt
