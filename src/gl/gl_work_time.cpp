#include "gl/gl_work_time.h"

#include "gl/gl_check.h"
#include "gl/gl_objects.h"

namespace glint {

double time_gl_work_ms(const std::function<void()>& work) {
  const GlQuery query = create_query(GL_TIME_ELAPSED);
  glBeginQuery(GL_TIME_ELAPSED, query.id());
  work();
  glEndQuery(GL_TIME_ELAPSED);
  GLuint64 nanoseconds = 0;
  glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &nanoseconds);  // waits for the work
  check_gl("timing GL work");
  return static_cast<double>(nanoseconds) * 1e-6;
}

}  // namespace glint
