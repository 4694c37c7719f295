#include "gl_rt/gl_job_buffer.h"

#include <algorithm>

namespace glint::gl_rt {

GLuint GlJobBuffer::hold(std::span<const glm::uvec4> jobs) {
  if (std::equal(jobs.begin(), jobs.end(), held_.begin(), held_.end())) return buffer_.id();
  if (jobs.size() > capacity_) {
    // Doubled, so a scene's meshes joining a few at a time do not reallocate every frame.
    capacity_ = std::max(jobs.size(), 2 * capacity_);
    buffer_ = create_buffer(capacity_ * sizeof(glm::uvec4), nullptr, GL_DYNAMIC_STORAGE_BIT);
  }
  glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(jobs.size_bytes()), jobs.data());
  held_.assign(jobs.begin(), jobs.end());
  return buffer_.id();
}

}  // namespace glint::gl_rt
