#include "gl/dispatch.h"

#include <string>

#include "gl/check.h"
#include "gl/error.h"

namespace sg::gl {

std::array<int, 2> group_counts(int width, int height, int local_x, int local_y) {
  if (width < 1 || height < 1 || local_x < 1 || local_y < 1)
    throw GlError("dispatch of " + std::to_string(width) + " x " + std::to_string(height) +
                  " in groups of " + std::to_string(local_x) + " x " + std::to_string(local_y) +
                  ": sizes must be positive");
  return {(width + local_x - 1) / local_x, (height + local_y - 1) / local_y};
}

void dispatch_2d(const Program& program, int width, int height) {
  const std::array<int, 3> local = program.local_size();
  if (local[0] == 0) throw GlError("dispatch_2d: not a compute program");
  if (local[2] != 1)
    throw GlError("dispatch_2d: the program's local_size_z is " + std::to_string(local[2]) +
                  ", not 1");
  const std::array<int, 2> groups = group_counts(width, height, local[0], local[1]);
  GLint max_x = 0, max_y = 0;
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 0, &max_x);
  glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1, &max_y);
  if (groups[0] > max_x || groups[1] > max_y)
    throw GlError("dispatch_2d: " + std::to_string(groups[0]) + " x " + std::to_string(groups[1]) +
                  " groups exceed GL_MAX_COMPUTE_WORK_GROUP_COUNT " + std::to_string(max_x) +
                  " x " + std::to_string(max_y));
  program.use();
  glDispatchCompute(GLuint(groups[0]), GLuint(groups[1]), 1);
  check_errors("glDispatchCompute(" + std::to_string(groups[0]) + ", " + std::to_string(groups[1]) +
               ", 1)");
}

void barrier(GLbitfield bits) {
  glMemoryBarrier(bits);
}

}  // namespace sg::gl
