// A buffer texture (samplerBuffer in GLSL, read with texelFetch(s, i)): a 1D array of
// RGBA32F texels in a buffer, for per-wave data (up to 65536 waves x a few texels: the GL
// limit GL_MAX_TEXTURE_BUFFER_SIZE is at least 65536 texels in 4.5, 2^27 on llvmpipe and
// NVIDIA). Texel i is floats [4i, 4i + 4) of the data (R32F: 1 float, RG32F: 2). Reads go
// through the texture cache, unlike an SSBO. The size is checked against the limit.
#pragma once

#include <epoxy/gl.h>

#include <span>

#include "gl/buffer.h"

namespace sg::gl {

class TextureBuffer {
 public:
  TextureBuffer() = default;
  // `data` holds texels x components floats (components from `format`: GL_R32F 1,
  // GL_RG32F 2, GL_RGBA32F 4).
  explicit TextureBuffer(std::span<const float> data, GLenum format = GL_RGBA32F);
  // `texels` texels of `format`, their contents undefined until a shader or update writes
  // them (a buffer the GPU fills).
  TextureBuffer(std::size_t texels, GLenum format);
  ~TextureBuffer();
  TextureBuffer(TextureBuffer&& o) noexcept;
  TextureBuffer& operator=(TextureBuffer&& o) noexcept;
  TextureBuffer(const TextureBuffer&) = delete;
  TextureBuffer& operator=(const TextureBuffer&) = delete;

  // Rewrites the texels from `first_texel` on (the size stays).
  void update(std::span<const float> data, std::size_t first_texel = 0);
  // glBindTextureUnit: the samplerBuffer declared with layout(binding = unit).
  void bind(GLuint unit) const;

  std::size_t texels() const { return texels_; }
  GLuint id() const { return texture_; }
  const Buffer& buffer() const { return buffer_; }

 private:
  Buffer buffer_;
  GLuint texture_ = 0;
  std::size_t texels_ = 0;
  int components_ = 4;
};

// GL_MAX_TEXTURE_BUFFER_SIZE of the current context, in texels.
int max_texture_buffer_texels();
// Throws GlError naming the limit when `texels` exceed it.
void check_texture_buffer_texels(std::size_t texels);

}  // namespace sg::gl
