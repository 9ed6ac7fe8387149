// `lean`'s map on the GPU (kernel/lean.glsl; methods/lean.h states the method): per frame,
// one compute pass fills level 0, a block of 4 x 4 texels an invocation, from the wave buffer
// with the kernel's lean_level0_block (the terms the CPU runs in SIMD lanes, each wave's
// row and column phases once a row and a column of the block), and one pass per
// level builds the MIP chain with lean_parent. The texels are five floats each in one R32F
// buffer texture, level after level, which the pixel program reads with the kernel's
// filters (binding 6); the passes write it as a storage buffer (binding 7), in bands of rows
// whose bytes fit the context's GL_MAX_SHADER_STORAGE_BLOCK_SIZE (128 MiB on llvmpipe, less
// than a 4096 map's level 0).
// 20 bytes a texel, N^2 4/3 texels: 447 MB at N = 4096; a map beyond the context's
// GL_MAX_TEXTURE_BUFFER_SIZE is refused naming --lean-size.
#pragma once

#include "gl/program.h"
#include "gl/texture_buffer.h"
#include "kernel/kernel_double.h"  // kLeanTexelFloats
#include "kernel/kernel_types.h"

namespace sg::gl_engine {

class LeanMapGl {
 public:
  LeanMapGl();
  // The map of p (size, levels) from the waves in `waves` for frame f (its uniforms as the
  // pixel program's). Keeps the storage while the size does not change.
  void fill(const gl::TextureBuffer& waves, const kf::Frame& f, const kf::LeanParams& p);
  // The texels of the last fill (unit: the pixel program's binding 6).
  const gl::TextureBuffer& texels() const { return texels_; }
  // An empty map of `size` texels a side is still allocated (the pixel program binds it).
  void allocate(int size);
  const gl::Program& program() const { return program_; }
  // The most bytes one pass writes through its storage binding: the context's limit, or
  // less (the tests' bands).
  void set_window_bytes(std::size_t bytes) { window_ = bytes; }
  // The passes of the last fill (bands of every level).
  int passes() const { return passes_; }

 private:
  gl::Program program_;
  gl::TextureBuffer texels_;
  int size_ = 0;
  std::size_t window_ = 0;  // 0: the context's limit
  int passes_ = 0;
};

}  // namespace sg::gl_engine
