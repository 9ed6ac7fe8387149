// Compute dispatch over a 2D image: one invocation per pixel in workgroups of the program's
// local size (16 x 16 or 8 x 8, declared in the shader's layout(local_size_x = ...)), the
// grid rounded up, so the shader must skip invocations outside the image:
//   if (any(greaterThanEqual(gl_GlobalInvocationID.xy, uvec2(size)))) return;
// The group counts are checked against GL_MAX_COMPUTE_WORK_GROUP_COUNT. After a dispatch,
// glMemoryBarrier (barrier()) before reading what it wrote, in GL or from the host.
#pragma once

#include <epoxy/gl.h>

#include <array>

#include "gl/program.h"

namespace sg::gl {

// The workgroup counts for width x height pixels in groups of local_x x local_y.
std::array<int, 2> group_counts(int width, int height, int local_x, int local_y);

// Binds `program` and dispatches width x height invocations in its local size (z = 1).
void dispatch_2d(const Program& program, int width, int height);

// glMemoryBarrier; the default covers image and buffer reads by later shaders and the host.
void barrier(GLbitfield bits = GL_ALL_BARRIER_BITS);

}  // namespace sg::gl
