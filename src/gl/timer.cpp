#include "gl/timer.h"

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {

GpuTimer::GpuTimer() {
  glCreateQueries(GL_TIMESTAMP, 2, queries_);
  check_errors("glCreateQueries(GL_TIMESTAMP)");
}

GpuTimer::~GpuTimer() {
  glDeleteQueries(2, queries_);
}

void GpuTimer::begin() {
  if (running_) throw GlError("GPU timer: begin while running");
  glQueryCounter(queries_[0], GL_TIMESTAMP);
  check_errors("glQueryCounter(GL_TIMESTAMP)");
  running_ = true;
}

void GpuTimer::end() {
  if (!running_) throw GlError("GPU timer: end without begin");
  glQueryCounter(queries_[1], GL_TIMESTAMP);
  running_ = false;
  done_ = true;
  check_errors("glQueryCounter(GL_TIMESTAMP)");
}

double GpuTimer::milliseconds() const {
  if (!done_ || running_) throw GlError("GPU timer: no time measured yet");
  GLuint64 t0 = 0, t1 = 0;
  glGetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &t0);  // waits for the result
  glGetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &t1);
  check_errors("glGetQueryObjectui64v(GL_QUERY_RESULT)");
  return t1 >= t0 ? double(t1 - t0) * 1e-6 : 0.0;
}

}  // namespace sg::gl
