#include "gl_engine/lean_map_gl.h"

#include <epoxy/gl.h>

#include <algorithm>

#include "base/error.h"
#include "gl/check.h"
#include "gl/dispatch.h"
#include "gl/error.h"
#include "gl_engine/kernel_program.h"
#include "gl_engine/uniforms.h"

namespace sg::gl_engine {

LeanMapGl::LeanMapGl() : program_(kernel_program(KernelEntry::lean_map, ProgramOptions{})) {}

void LeanMapGl::allocate(int size) {
  if (size == size_) return;
  const size_t floats = size_t(kd::lean_level_offset(size, kd::lean_level_count(size))) *
                        size_t(kd::kLeanTexelFloats);
  if (floats > size_t(gl::max_texture_buffer_texels())) {
    throw Error("--lean-size " + std::to_string(size) + ": the map's " + std::to_string(floats) +
                " floats exceed this GL context's GL_MAX_TEXTURE_BUFFER_SIZE of " +
                std::to_string(gl::max_texture_buffer_texels()) + " (use a smaller map)");
  }
  texels_ = gl::TextureBuffer(floats, GL_R32F);
  size_ = size;
}

void LeanMapGl::fill(const gl::TextureBuffer& waves, const kf::Frame& f, const kf::LeanParams& p) {
  allocate(p.size);
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  GLint align = 1;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  const size_t window = window_ > 0 ? std::min(window_, size_t(limit)) : size_t(limit);
  const size_t total = texels_.buffer().size();
  const size_t texel_bytes = size_t(kd::kLeanTexelFloats) * sizeof(float);
  UniformWriter u(program_);
  set_uniforms(u, "frame", f);
  set_uniforms(u, "lparams", p);
  waves.bind(1);
  texels_.bind(6);
  passes_ = 0;
  for (int level = 0; level < p.levels; ++level) {
    program_.set("lean_level", level);
    const int n = p.size >> level;
    const size_t level_at = size_t(kd::lean_level_offset(p.size, level)) * texel_bytes;
    // Rows a band: its texels and the window's alignment slack within the window.
    const size_t row_bytes = size_t(n) * texel_bytes;
    if (row_bytes + size_t(align) > window)
      throw Error("--lean-size " + std::to_string(p.size) +
                  ": a row of the map exceeds this GL context's storage-block size");
    const int band = int(std::min<size_t>(size_t(n), (window - size_t(align)) / row_bytes));
    for (int row0 = 0; row0 < n; row0 += band) {
      const int rows = std::min(band, n - row0);
      const size_t first = level_at + size_t(row0) * row_bytes;
      const size_t start = first / size_t(align) * size_t(align);
      const size_t bytes = std::min(total - start, (first - start) + size_t(rows) * row_bytes);
      texels_.buffer().bind_range(GL_SHADER_STORAGE_BUFFER, 7, start, bytes);
      program_.set("lean_row0", row0);
      program_.set("lean_rows", rows);
      program_.set("lean_out_base", int(start / sizeof(float)));
      // Level 0 a block of texels an invocation (kernel/lean.glsl, lean_level0_block).
      const int per = level == 0 ? kd::kLeanBlock : 1;
      gl::dispatch_2d(program_, (n + per - 1) / per, (rows + per - 1) / per);
      // The next level reads this one through the texture cache.
      gl::barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
      ++passes_;
    }
  }
  gl::check_errors("LEAN map");
}

}  // namespace sg::gl_engine
